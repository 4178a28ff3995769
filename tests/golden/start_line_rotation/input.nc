(A closed square: the point file starts at the move of line 5, as the seed's start point)
G90 G92 X0 Y0
G01 X10. Y0
X10. Y10.
X0 Y10.
X0 Y0
M02
