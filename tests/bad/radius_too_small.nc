; 4:13: error: arc radius 4.000 is shorter than half the chord 5.000 mm [K0302]
G21 G90
G01 X0 Y0
G02 X10. Y0 R4.
M02
