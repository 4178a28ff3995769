(The same die with NCVC's conical corner [G61]: the upper fillet is the taper's offset of the)
(lower one, concentric, its radius 2 - 20 tan 3 = 0.952 mm.)
G92 X20. Y10. I20. J0
G90 G61 G51 T3.
G01 X20. Y0
X40. R2.
Y20. R2.
X0 R2.
Y0 R2.
X20.
G50
G01 X20. Y10.
M02
