; The same die with its contour in a subprogram, called once per pass: the lead-in with G41 or
; G42 and the register in the main program, the contour in O100, the lead-out with G40. The skim
; runs the same way as the rough cut (G41 both): passes are found from the geometry, not comments.
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 2 passes
; expect: pass 1: lines 12-14, G41 H001 = 0.180 mm, counter-clockwise, closes, 98.200 mm
; expect: pass 2: lines 15-17, G41 H002 = 0.110 mm, counter-clockwise, closes, 98.900 mm
O0001;
H001 = +000000.1800;
H002 = +000000.1100;
G90 G92 X0 Y0;
G41 H001 G01 X10. Y0;
M98 P100;
G40 G01 X0 Y0;
G41 H002 G01 X10. Y0;
M98 P100;
G40 G01 X0 Y0;
M02;
O100;
G01 Y10.;
X-10.;
Y-10.;
X10.;
Y0;
M99;
