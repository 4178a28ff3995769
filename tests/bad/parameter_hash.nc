; 2:1: error: unexpected '#' in a block [K0106]
#1=5
M02
