(Bad part: a 10 degree taper over 25 mm moves the upper contour 4.4 mm inwards; the 2 mm wide)
(tab on the right is narrower than twice that, so on the upper plane its end is swallowed: the)
(offsets of its two sides cross before they reach it. The R2 corners shrink to sharp corners,)
(which is only a warning.)
(taper-angle, Fanuc/NCVC words; G92 I is the thickness.)
(Expect: error K0221)
%
G92 X0 Y-15. I25. J0
G51 T10.
G01 X0 Y-10.
X8.
G03 X10. Y-8. I0 J2.
G01 Y-1.
X15.
Y1.
X10.
Y8.
G03 X8. Y10. I-2. J0
G01 X-8.
G03 X-10. Y8. I0 J-2.
G01 Y-8.
G03 X-8. Y-10. I2. J0
G01 X0
G50
G01 X0 Y-15.
M02
%
