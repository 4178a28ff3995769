; 2:5: error: unexpected byte 0x07 in a block [K0106]
G01 X1.
M02
