; 2:5: error: expected a number after 'X', read 'N' [K0102]
G01 XNAN Y0
M02
