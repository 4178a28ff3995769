; 2:1: error: arc needs its centre (I J) or its radius (R) [K0301]
G02 X10. Y0
M02
