x = 1e308 * 10;
cube(x);