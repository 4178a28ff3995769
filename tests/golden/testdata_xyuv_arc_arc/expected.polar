(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
G21 G90
G92 X0.000 C0.000
G01 X0.020 C0.000
X0.022 C19.576
X0.030 C28.675
X0.044 C26.565
M30
