; A die whose rough cut and skim leave a 2 mm tab; a stop (M01) to secure the slug; a cut-off.
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 3 passes
; expect: pass 1: lines 11-17, G41 H001 = 0.180 mm, counter-clockwise, leaves a tab of 2.000 mm
; expect: pass 2: lines 18-24, G42 H002 = 0.110 mm, clockwise, leaves a tab of 2.000 mm
; expect: pass 3: lines 26-28, G41 H001 = 0.180 mm, neither, cuts off the tab, 21.842 mm
; expect diagnostic: 27 K0614
H001 = +000000.1800;
H002 = +000000.1100;
G90 G92 X0 Y0;
G41 H001 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y-2.;
G40 G01 X0 Y0;
G42 H002 G01 X10. Y-2.;
Y-10.;
X-10.;
Y10.;
X10.;
Y0;
G40 G01 X0 Y0;
M01;
G41 H001 G01 X10. Y-2.;
Y0;
G40 G01 X0 Y0;
M02;
