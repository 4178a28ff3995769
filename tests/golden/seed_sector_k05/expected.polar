%
(written by Kerf: polar X/C from input.nc; X diameter, C degrees unwrapped; the spiral between points within 0.0010 mm)
(Kerf sample: the seed paper's test part, a 90-degree circular sector of radius 40 mm.)
(Slusarczyk cut it on a BP-95d in 1.5 mm stainless steel with interpolation steps of)
(0.1, 0.5 and 1 mm, to see how the step changes the arc. Try:)
(  kerf check samples/sector_r40.nc)
(  kerf explain samples/sector_r40.nc --step 1)
(  kerf convert samples/sector_r40.nc --to bp95d --step 0.5 -o sector.txt)
(The wire starts in a hole 5 mm left of the apex, cuts the sector counter-clockwise)
(and returns to the hole along its lead-in, which `kerf check` notes as a retrace.)
O0001
G21 G90 G17
G92 X10.000 C-180.000
G01 X0.000 C-180.000 F2.
X0.000 C-360.000
X80.000 C-360.000
X80.000 C-315.000
X80.000 C-270.000
X0.000 C-270.000
X0.000 C-180.000
X10.000 C-180.000
M02
%
