; 4:6: error: ',R1.': no cut move follows: there is no corner to round [K0240]
G90 G92 X0 Y0
G01 X10.
Y10. ,R1.
M02
