; 2:13: error: U/V give the upper contour of a 4-axis taper program, which this version does not read [K0206]
G01 X1. Y1. U2. V3.
M02
