; 5:5: error: on the upper plane the corner's radius 0.500 mm does not fit between the taper's offset elements: it is left sharp there [K0240]
G92 X0 Y0 I20. J0
G90 G51 T5.
G01 X1. Y0
X3. R0.5 K0.5
Y1.
G50
G01 X0 Y0
M02
