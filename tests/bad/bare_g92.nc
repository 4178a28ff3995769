; 3:1: error: G92 needs the coordinates of the current position (X, Y) [K0209]
G01 X5. Y0
G92
G01 X10.
M02
