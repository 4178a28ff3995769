; 3:10: error: ',C1.': this block's element and the next meet tangent: no corner [K0240]
G90 G92 X0 Y0
G01 X10. ,C1.
X20.
M02
