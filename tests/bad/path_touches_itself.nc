; 6:1: error: the cut path touches itself at (5.000, 0.000): this move meets the move on line 4 [K0602]
G90
G92 X0 Y0
G01 X10. Y0
X10. Y10.
X5. Y0
X0 Y10.
X0 Y0
M02
