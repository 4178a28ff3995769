; 2:5: error: 'X1,5' has a comma where a decimal point belongs: NC numbers take a point [K0112]
G01 X1,5 Y2.
M02
