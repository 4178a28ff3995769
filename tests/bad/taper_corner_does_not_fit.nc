; 6:6: error: on the upper plane the corner's radius 20.000 mm does not fit between the taper's offset elements: it is left sharp there [K0240]
G92 X20. Y10. I20. J0
G90 G51 T3.
G01 X20. Y0
X40. R2.
Y20. R2. K20.
X0 R2.
Y0 R2.
X20.
G50
G01 X20. Y10.
M02
