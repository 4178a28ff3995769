(Taper punch: a 20 x 20 mm square with R3 corners, 25 mm thick, 2 degree draft.)
(Dialect taper-angle, Fanuc/NCVC words: G51 leans the wire to the left of travel, T the angle.)
(Cut counter-clockwise, so left is inwards: the punch is 20 x 20 at the bottom and smaller on top.)
(Heights: G92 I = thickness 25, J = program plane 0 - the contour below is the lower contour.)
(The taper starts on the lead-in line and ends on the lead-out line, never on an arc.)
(Expected: kerf check says ok. The wire leans 2 degrees along the sides and arcs; where the taper)
(starts and ends, at the sharp corner of the lead-in, the wire leans along the diagonal: 2.83 degrees.)
%
O0100
G90 G92 X0 Y-15. I25. J0
G51 T2.
G01 X0 Y-10. F2.
X7.
G03 X10. Y-7. I0 J3.
G01 Y7.
G03 X7. Y10. I-3. J0
G01 X-7.
G03 X-10. Y7. I0 J-3.
G01 Y-7.
G03 X-7. Y-10. I3. J0
G01 X0
G50
G01 X0 Y-15.
M02
%
