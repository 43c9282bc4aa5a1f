outer
0 0
0 0
0 0
