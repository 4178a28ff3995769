; 4:19: error: upper arc needs its centre (I J) or its radius (R) [K0301]
M101 P20
G92 X0 Y0 U0 V0
G2 X10. Y0 I5. J0 G2 U10. V0
M2
