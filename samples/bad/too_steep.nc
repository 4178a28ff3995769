(Bad part: the wire leans 38.7 degrees, beyond the 30 degrees a typical machine tilts.)
(xyuv-abs: a 10 x 10 square below, the same square 8 mm to the right 10 mm above.)
(Expect: error K0650)
%
M101 P10
G92 X0 Y0 U8. V0
G1 X10. Y0 G1 U18. V0
G1 X10. Y10. G1 U18. V10.
G1 X0 Y10. G1 U8. V10.
G1 X0 Y0 G1 U8. V0
M2
%
