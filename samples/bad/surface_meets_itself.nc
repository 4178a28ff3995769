(Bad part: both contours are simple quadrilaterals, but half-way up the surface passes through)
(itself: the corner at 8,1 below [0,1 above] dips under the side that starts at 0,0, so the)
(side from that corner to the next crosses it. Nothing on either plane shows it.)
(xyuv-abs, 20 mm thick.)
(Expect: error K0651)
%
M101 P20
G92 X0 Y0 U0 V0
G1 X10. Y0 G1 U10. V8.
G1 X8. Y1. G1 U0 V1.
G1 X2. Y3. G1 U-2. V4.
G1 X0 Y0 G1 U0 V0
M2
%
