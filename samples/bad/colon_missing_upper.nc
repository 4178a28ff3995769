(Bad part: inside G141 every move must give its upper contour after ':', and one does not:)
(the two planes would have different block counts.)
(sodick-colon; TP is taken as the upper plane.)
(Expect: error K0226)
TN0 TP20.
G90 G92 X0 Y0
G141
G01 X10. Y0 : G01 X10. Y0
G01 X10. Y10.
G01 X0 Y10. : X0 Y10.
G01 X0 Y0 : X0 Y0
G140
M02
