(Bad part: the lower contour closes its square, the upper one stops 3 mm short.)
(xyuv-abs, 20 mm thick.)
(Expect: error K0655)
%
M101 P20
G92 X0 Y0 U0 V0
G1 X10. Y0 G1 U10. V0
G1 X10. Y10. G1 U10. V10.
G1 X0 Y10. G1 U0 V10.
G1 X0 Y0 G1 U0 V3.
M2
%
