x = 0/0;
sphere(x);