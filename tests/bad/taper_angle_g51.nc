; 2:1: error: G51 is a taper command: 4-axis taper programs are not read by this version [K0206]
G51 A2.
M02
