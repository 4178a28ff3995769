(Charmilles Robofil: the die with its corners programmed as arcs of R 2 [absolute I J centres],)
(3 degrees outwards under G29: the arcs are tapered into cylinders, R 2 on both faces, tangent to)
(each face's offset sides [without G29 they would be cones, R 2 + 20 tan 3 on the upper face].)
G90 G92 X20. Y10.
G29
G52 A3.
G01 X20. Y0
X38.
G03 X40. Y2. I38. J2.
G01 Y18.
G03 X38. Y20. I38. J18.
G01 X2.
G03 X0 Y18. I2. J18.
G01 Y2.
G03 X2. Y0 I2. J2.
G01 X20.
G50
G01 X20. Y10.
M02
