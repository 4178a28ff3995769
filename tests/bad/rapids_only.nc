; 3:1: error: the program cuts nothing (no G01, G02 or G03 move) [K0606]
G90 G92 X0 Y0
G00 X5. Y5.
G00 X0 Y0
M02
