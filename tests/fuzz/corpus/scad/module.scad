module m() { cube(1); }
m();