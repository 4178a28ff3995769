(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
(I J written as start minus centre, as some Agie/Charmilles/Mitsubishi posts do)
X40.000 C0.000 G92
G01 X20.000 C0.000
X20.000 C45.000
X20.000 C90.000
X20.000 C135.000
X20.000 C180.000
X20.000 C225.000
X20.000 C270.000
X20.000 C315.000
X20.000 C360.000
X40.000 C360.000
M02
