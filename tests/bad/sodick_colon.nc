; 2:13: error: ':' separates lower and upper contours (Sodick 4-axis taper), which this version does not read [K0206]
G01 X1. Y1. : G01 X2. Y2.
M02
