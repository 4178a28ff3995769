; 2:17: error: '(' inside a comment: comments cannot nest [K0109]
G01 X1. (corner (outer) )
M02
