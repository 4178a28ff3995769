; 3:5: error: taper angle 46.000 degrees is beyond 45 degrees, the limit NC controls accept [K0218]
G92 I20.
G51 A46.
G01 X5.
M02
