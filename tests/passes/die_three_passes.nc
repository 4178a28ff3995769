; A die opening 20 x 20 mm cut in three passes from a start hole at its centre, as a Sodick or
; Fanuc shop writes it: an H table, the rough cut G41 H001 counter-clockwise, a skim G42 H002
; clockwise, a skim G41 H003 counter-clockwise; each led in from the hole and out with G40.
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 3 passes
; expect: pass 1: lines 13-19, G41 H001 = 0.180 mm, counter-clockwise, closes, 98.200 mm
; expect: pass 2: lines 20-26, G42 H002 = 0.110 mm, clockwise, closes, 98.900 mm
; expect: pass 3: lines 27-33, G41 H003 = 0.085 mm, counter-clockwise, closes, 99.150 mm
H001 = +000000.1800;
H002 = +000000.1100;
H003 = +000000.0850;
G90 G92 X0 Y0;
G41 H001 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y0;
G40 G01 X0 Y0;
G42 H002 G01 X10. Y0;
Y-10.;
X-10.;
Y10.;
X10.;
Y0;
G40 G01 X0 Y0;
G41 H003 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y0;
G40 G01 X0 Y0;
M02;
