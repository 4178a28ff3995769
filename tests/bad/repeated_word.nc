; 2:9: error: word 'X' appears twice in one block [K0108]
G01 X1. X2.
M02
