; 5:1: error: the wire offset is cancelled (G40 on line 4) on this arc: a control cancels it on a straight move [K0229]
G92 X0 Y0
G41 D1 G01 X5. Y0
G40
G02 X15. Y0 I5. J0
M02
