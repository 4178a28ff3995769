; 2:5: error: G02 and G01 are in the same group and cannot share a block [K0203]
G01 G02 X1. Y1. R1.
M02
