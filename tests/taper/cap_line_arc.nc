(A 30 x 20 mm outline whose right end is an arc of radius 15 mm bulging outwards: each corner)
(between a side and the arc rounded with ,R1. on the block before it: line to arc, arc to line.)
(Checked against GEOS: the outline opened by 1 mm.)
G90 G92 X10. Y0
G01 X30. ,R1.
G03 X30. Y20. R15. ,R1.
G01 X0 ,R1.
Y0 ,R1.
X10.
M02
