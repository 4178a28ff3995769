(Bad part: at the corner 10,0 the surface folds back on itself 15 mm up: there the side)
(from 10,0 runs straight back along the side that led to it.)
(xyuv-abs, 30 mm thick.)
(Expect: error K0654)
%
M101 P30
G92 X0 Y0 U0 V0
G1 X10. Y0 G1 U10. V0
G1 X10. Y10. G1 U0 V-10.
G1 X0 Y10. G1 U-10. V0
G1 X0 Y0 G1 U0 V0
M2
%
