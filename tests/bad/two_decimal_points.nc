; 2:5: error: number has a second decimal point [K0103]
G01 X1.2.3 Y0
M02
