; 2:5: error: number has more than 18 digits [K0105]
G01 X1234567890123456789 Y0
M02
