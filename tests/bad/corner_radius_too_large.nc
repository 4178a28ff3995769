; 3:9: error: ',R5.': a radius 5.000 mm corner needs more than this block's element or the next one (line 4) has [K0240]
G90 G92 X0 Y0
G01 X4. ,R5.
Y10.
M02
