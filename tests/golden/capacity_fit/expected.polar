(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
(A disc of radius 25 with a lead-in: fit the points to a controller that holds 60)
X60.000 C-180.000 G92
G01 X50.000 C-180.000
X50.000 C-225.000
X50.000 C-270.000
X50.000 C-315.000
X50.000 C-360.000
X50.000 C-405.000
X50.000 C-450.000
X50.000 C-495.000
X50.000 C-540.000
X60.000 C-540.000
M02
