(A die 40 x 20 mm, 20 mm thick, the wire leaning 5 degrees left of travel from the lower face -)
(the program plane, G92 J0. Read with --guides -30,50: the lower guide 30 mm below the work, the)
(upper 50 mm above its lower face. US 4700314's extrapolation: at the lower guide the wire is)
(d1 = 30 tan 5 = 2.6247 mm right of the programmed contour, at the upper d2 = 50 tan 5 = 4.3744 mm)
(left of it; the guides' spread, 80 mm, is four times the work's, so U/V between them reach 4 x 20)
(tan 5 = 6.9991 mm.)
G92 X20. Y10. I20. J0
G90 G51 T5.
G01 X20. Y0
X40.
Y20.
X0
Y0
X20.
G50
G01 X20. Y10.
M02
