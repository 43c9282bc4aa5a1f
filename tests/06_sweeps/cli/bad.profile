# a profile with a bad line
outer
0 0
1 0 oops
0 1
