; 3:10: error: ',R1.': a rapid follows, not a cut move: there is no corner to round [K0240]
G90 G92 X0 Y0
G01 X10. ,R1.
G00 X20. Y5.
M02
