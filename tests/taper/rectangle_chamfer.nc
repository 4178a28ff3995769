(A 40 x 20 mm outline with each corner chamfered 1.5 mm: ,C 1.5 on each corner's block.)
(By hand: each chamfer joins the points 1.5 mm from the corner along both sides.)
G90 G92 X20. Y0
G01 X40. ,C1.5
Y20. ,C1.5
X0 ,C1.5
Y0 ,C1.5
X20.
M02
