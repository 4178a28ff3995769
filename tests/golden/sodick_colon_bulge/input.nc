(Sodick 4-axis program: the lower contour before ':', the upper contour after it; each side)
(keeps its own modal G code. Below, a 30 x 20 rectangle; above, the same rectangle with its)
(right side bulged out into an arc of radius 12.5, 5 mm proud. The taper is G141 ... G140.)
(Heights: TN0 is the lower plane, TP20. the program plane, taken as the upper plane 20 mm up.)
(Expected: kerf check says ok; the steepest wire is 14.0 degrees, mid-way along the bulge.)
TN0 TP20.
G90 G92 X15. Y-5.
G141
G01 X15. Y0 : G01 X15. Y0
G01 X30. Y0 : X30. Y0
G01 X30. Y20. : G03 X30. Y20. I-7.5 J10.
G01 X0 Y20. : G01 X0 Y20.
G01 X0 Y0 : X0 Y0
G01 X15. Y0 : X15. Y0
G140
G01 X15. Y-5.
M02
