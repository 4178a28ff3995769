; 2:1: error: expected a number after 'G', read 'O' [K0102]
GO1 X5.
M02
