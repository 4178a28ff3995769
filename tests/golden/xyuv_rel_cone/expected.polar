(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
G00 X0.000 C0.000
G01 X20.000 C0.000
X20.000 C0.000
X0.000 C0.000
M30
