# The issue's profile: a 4×4 square with a centred 2×2 hole, centre 2 from the z-axis (x = r in [0, 4]).
# `geolab sweep square_hole.profile --revolve 360 --out ring.stl` gives V → 48π, A → 96π (Pappus).
outer
0 -2
4 -2
4 2
0 2
hole     # clockwise
1 -1
1 1
3 1
3 -1
