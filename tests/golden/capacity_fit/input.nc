(A disc of radius 25 with a lead-in: fit the points to a controller that holds 60)
G90 G92 X-30. Y0
G01 X-25. Y0
G02 I25. J0
G01 X-30. Y0
M02
