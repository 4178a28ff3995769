; 2:1: error: G92 needs the coordinates of the current position (X, Y) [K0209]
G92
M02
