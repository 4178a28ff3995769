(A 40 x 20 mm punch outline, each corner rounded with Fanuc's optional corner word ,R 2.)
(The start point lies on the bottom side, so the whole cut is the rounded rectangle.)
(By hand: four sides trimmed 2 mm at each end, four quarter circles of radius 2 mm about)
(2 2, 38 2, 38 18 and 2 18; length 2 x 36 + 2 x 16 + 2 pi 2 = 116.566 mm.)
G90 G92 X20. Y0
G01 X40. ,R2.
Y20. ,R2.
X0 ,R2.
Y0 ,R2.
X20.
M02
