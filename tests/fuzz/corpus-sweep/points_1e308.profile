outer
0 0
1e308 0
0 1e308
