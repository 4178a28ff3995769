(A taper square, 20 mm below and 18 mm above, its upper plane turned 1 degree)
(about the centre: taper_square.dxf draws both planes as meant, layers LOWER and UPPER)
G90 G21
G92 X0 Y-15 U0 V-15
G01 X0 Y-10 U0.1571 V-8.9986
G01 X10 Y-10 U9.1557 V-8.8416
G01 X10 Y10 U8.8416 V9.1557
G01 X-10 Y10 U-9.1557 V8.8416
G01 X-10 Y-10 U-8.8416 V-9.1557
G01 X0 Y-10 U0.1571 V-8.9986
G01 X0 Y-15 U0 V-15
M02
