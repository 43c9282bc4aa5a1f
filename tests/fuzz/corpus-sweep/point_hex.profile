outer
0 0
0x1p0 0
0 1
