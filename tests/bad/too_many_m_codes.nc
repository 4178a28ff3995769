; 2:17: error: more than 4 M codes in one block [K0111]
M00 M01 M05 M08 M09 G01 X1.
M02
