// The classic CSG logo: a cube intersected with a sphere, minus three cylinders along x, y and z.
// (lab 07's OpenSCAD subset: see lib/include/geolab/scad.hpp; $fn is accepted and ignored — the solids are exact.)
size = 2;          // edge of the cube
ball = 1.3;        // sphere radius (cuts the cube's corners)
hole = 0.55;       // radius of the three holes
$fn = 64;

difference() {
    intersection() {
        cube(size, center = true);
        sphere(r = ball);
    }
    union() {
        cylinder(h = 2 * size, r = hole, center = true);                     // along z
        rotate([90, 0, 0]) cylinder(h = 2 * size, r = hole, center = true);  // along y
        rotate([0, 90, 0]) cylinder(h = 2 * size, r = hole, center = true);  // along x
    }
}
