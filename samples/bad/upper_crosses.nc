(Bad part: the upper contour crosses itself - a square below, a bow tie above.)
(xyuv-abs; the lower contour is fine, the upper one's second and fourth sides cross.)
(Expect: error K0601)
%
M101 P30
G92 X0 Y0 U0 V0
G1 X10. Y0 G1 U10. V0
G1 X10. Y10. G1 U0 V10.
G1 X0 Y10. G1 U10. V10.
G1 X0 Y0 G1 U0 V0
M2
%
