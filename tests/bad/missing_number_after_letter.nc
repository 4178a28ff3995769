; 3:5: error: expected a number after 'X', read the end of the line [K0102]
G21 G90
G01 X
