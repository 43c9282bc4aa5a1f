// A mechanical angle bracket: two plates at a right angle, a triangular gusset made from a cube cut by a
// rotated cube, two countersunk bolt holes (cylinder + cone) in the base and a slot in the upright.
t = 6;        // plate thickness
w = 40;       // width (along y)
l = 60;       // base length (along x)
h = 50;       // upright height (along z)
bolt = 3.4;   // bolt hole radius

difference() {
    union() {
        cube([l, w, t]);                          // base plate
        cube([t, w, h]);                          // upright plate
        // gusset: a block in the corner, cut along its diagonal
        translate([t, w / 2 - t / 2, t])
            difference() {
                cube([25, t, 25]);
                translate([25, -1, 0]) rotate([0, -45, 0]) cube([40, t + 2, 40]);
            }
    }
    // two bolt holes in the base, each with a countersink cone
    translate([l - 12, 10, -1]) cylinder(h = t + 2, r = bolt);
    translate([l - 12, w - 10, -1]) cylinder(h = t + 2, r = bolt);
    translate([l - 12, 10, t - 2]) cylinder(h = 2.01, r1 = bolt, r2 = bolt + 2.5);
    translate([l - 12, w - 10, t - 2]) cylinder(h = 2.01, r1 = bolt, r2 = bolt + 2.5);
    // a slot in the upright: a box with rounded ends (two cylinders)
    translate([-1, w / 2 - 8, h - 18]) cube([t + 2, 16, 2 * bolt]);
    translate([-1, w / 2 - 8, h - 18 + bolt]) rotate([0, 90, 0]) cylinder(h = t + 2, r = bolt);
    translate([-1, w / 2 + 8, h - 18 + bolt]) rotate([0, 90, 0]) cylinder(h = t + 2, r = bolt);
}
