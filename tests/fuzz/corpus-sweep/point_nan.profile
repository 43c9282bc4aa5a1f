outer
0 0
1 0
nan 1
