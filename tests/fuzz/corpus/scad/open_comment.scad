/* never closed
cube(1);