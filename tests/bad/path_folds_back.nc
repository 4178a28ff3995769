; 5:1: error: this move folds back over the previous one (line 4) near (7.000, 0.000) [K0603]
G90
G92 X0 Y0
G01 X10. Y0
X4.
M02
