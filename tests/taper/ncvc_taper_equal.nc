(NCVC wire mode: a die 40 x 20 mm, 20 mm thick, 3 degrees leaning left of travel [G51 T3.],)
(program plane on the lower face [G92 I20. J0], each corner R2. on its cut block: NCVC's default)
(corner, G60, has the same radius 2 mm on both planes, tangent to each plane's offset sides.)
G92 X20. Y10. I20. J0
G90 G51 T3.
G01 X20. Y0
X40. R2.
Y20. R2.
X0 R2.
Y0 R2.
X20.
G50
G01 X20. Y10.
M02
