(An L-shaped punch: its inside corner rounded with ,R3. and its outside corners with ,R1.)
(Checked against GEOS: the polygon closed by 3 mm, then opened by 1 mm.)
G90 G92 X15. Y0
G01 X30. ,R1.
Y10. ,R1.
X10. ,R3.
Y30. ,R1.
X0 ,R1.
Y0 ,R1.
X15.
M02
