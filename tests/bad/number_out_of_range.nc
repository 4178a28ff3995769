; 2:5: error: number is out of range (limit 1e9) [K0105]
G01 X1000000000. Y0
M02
