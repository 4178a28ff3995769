; 4:1: error: the wire offset is started (G41 on line 4) on this arc: a control starts it on a straight move [K0229]
G92 X0 Y0
G01 X5. Y0
G41 D1 G03 X15. Y0 I5. J0
M02
