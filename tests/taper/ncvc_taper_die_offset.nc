(NCVC wire mode: a die 40 x 20 mm with corners R2., 20 mm thick, cut counter-clockwise under G41)
(D1 = 0.15 mm inside it, the wire leaning 2 degrees right of travel: outwards, G52 T2.. The wire)
(offset applies on the program plane - the lower face, G92 J0 - and the taper is taken from the)
(offset path; the corners are equal-radius [G60, NCVC's default]: the part's R2. on both faces,)
(so the wire's path has R 1.85 on both planes. Read with --offset 0.15.)
G92 X20. Y10. I20. J0
G90 G52 T2.
G41 D1 G01 X20. Y0
X40. R2.
Y20. R2.
X0 R2.
Y0 R2.
X20.
G50
G40 G01 X20. Y10.
M02
