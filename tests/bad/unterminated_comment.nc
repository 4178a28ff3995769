; 3:5: error: comment is not closed on its line [K0101]
G21
G01 (no closing bracket X1.
M02
