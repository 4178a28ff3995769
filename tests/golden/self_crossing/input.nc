; 6:1: error: the cut path crosses itself at (5.000, 5.000): this move crosses the move on line 4 [K0601]
G21 G90
G92 X0 Y0
G01 X10. Y10.
X10. Y0
X0 Y10.
X0 Y0
M02
