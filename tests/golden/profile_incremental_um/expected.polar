(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
(Output through a custom profile: micrometre integers, incremental, numbered, with header)
X0.000 C0.000 G92
G01 X20.000 C0.000
X20.000 C45.000
X20.000 C90.000
X0.000 C90.000
M02
