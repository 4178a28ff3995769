; 2:5: error: exponent notation is not allowed in NC words [K0104]
G01 X1e999 Y0
M02
