; 2:3: error: expected a number after 'L', read 'X' [K0102]
G0l X5.
M02
