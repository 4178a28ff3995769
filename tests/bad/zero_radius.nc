; 2:13: error: arc radius is zero [K0305]
G03 X0 Y0.5 I0 J0
M02
