(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
G00 X10.000 C-180.000
G01 X0.000 C-180.000 F2.000
X0.000 C-360.000
X80.000 C-360.000
X80.000 C-315.000
X80.000 C-270.000
X0.000 C-270.000
X0.000 C-180.000
X10.000 C-180.000
M30
