; 2:7: error: unexpected ',' in a block [K0106]
G01 X1,5 Y2.
M02
