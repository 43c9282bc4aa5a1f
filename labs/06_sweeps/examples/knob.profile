# A six-pointed star (12 vertices) (radii 12 and 8 mm) with a 3 mm bore: `geolab sweep knob.profile --extrude 20 --steps 40
# --twist 1 --scale 0.8 --out knob.stl` writes the handout's print-ready knob.
outer
12 0
6.928203 4
6 10.392305
0 8
-6 10.392305
-6.928203 4
-12 0
-6.928203 -4
-6 -10.392305
0 -8
6 -10.392305
6.928203 -4
hole
3 0
2.598076 -1.5
1.5 -2.598076
0 -3
-1.5 -2.598076
-2.598076 -1.5
-3 0
-2.598076 1.5
-1.5 2.598076
0 3
1.5 2.598076
2.598076 1.5
