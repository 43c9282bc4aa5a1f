#!/bin/bash
# Renders lab 03's handout figures with `geolab quadric render` (the reference in the instructor's tree).
G=$1; OUT=$2
set -e
while read -r name coeffs; do
  [ -z "$name" ] && continue
  $G quadric render $coeffs --box 2 --width 240 --height 180 --png $OUT/$name.png > /dev/null
  echo "$name: $($G quadric classify $coeffs | head -1)"
done <<'LIST'
real_ellipsoid 0.444 1 1.778 0 0 0 0 0 0 -1
imaginary_ellipsoid 1 1 1 0 0 0 0 0 0 1
hyperboloid_one_sheet 1 1 -1 0 0 0 0 0 0 -1
hyperboloid_two_sheets 1 1 -1 0 0 0 0 0 0 1
real_cone 1 1 -1 0 0 0 0 0 0 0
imaginary_cone 1 1 1 0 0 0 0 0 0 0
elliptic_paraboloid 1 1 0 0 0 0 0 0 -0.5 0
hyperbolic_paraboloid 1 -1 0 0 0 0 0 0 -0.5 0
real_elliptic_cylinder 1 0.5 0 0 0 0 0 0 0 -1
imaginary_elliptic_cylinder 1 1 0 0 0 0 0 0 0 1
hyperbolic_cylinder 1 -1 0 0 0 0 0 0 0 -0.5
parabolic_cylinder 1 0 0 0 0 0 0 0 -0.5 0
real_intersecting_planes 1 -1 0 0 0 0 0 0 0 0
imaginary_intersecting_planes 1 1 0 0 0 0 0 0 0 0
real_parallel_planes 1 0 0 0 0 0 0 0 0 -1
imaginary_parallel_planes 1 0 0 0 0 0 0 0 0 1
coincident_planes 1 0 0 0 0 0 0 0 0 0
LIST
for e1 in 0.25 1 2 3; do for e2 in 0.25 1 2 3; do
  $G quadric render --superquadric $e1 $e2 --width 160 --height 120 --png $OUT/sq_${e1}_${e2}.png > /dev/null
done; done
echo superquadrics done
