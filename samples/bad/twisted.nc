(Bad part: the upper square is the lower one turned by 120 degrees about its centre, so on every)
(side the upper guide travels 120 degrees away from the lower one: the surface twists through itself.)
(xyuv-abs, 30 mm thick.)
(Expect: error K0653)
%
M101 P30
G92 X0 Y0 U11.830 V-1.830
G1 X10. Y0 G1 U6.830 V6.830
G1 X10. Y10. G1 U-1.830 V11.830
G1 X0 Y10. G1 U3.170 V3.170
G1 X0 Y0 G1 U11.830 V-1.830
M2
%
