; 3:15: error: a block rounds or chamfers its corner once: one ,R or ,C [K0108]
G90 G92 X0 Y0
G01 X10. ,R1. ,C1.
Y10.
M02
