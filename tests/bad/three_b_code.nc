; 2:23: error: a lost B: the y field starts with a number, not with B [K0120]
B9900B0B9900GXL3B9900 9900B9900GXL1
DD
