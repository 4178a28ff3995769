(The same die with NCVC's independent corners [G60 R K]: radius 2 mm on the lower plane, 3 mm)
(on the upper, each tangent to its plane's offset sides.)
G92 X20. Y10. I20. J0
G90 G60 G51 T3.
G01 X20. Y0
X40. R2. K3.
Y20. R2. K3.
X0 R2. K3.
Y0 R2. K3.
X20.
G50
G01 X20. Y10.
M02
