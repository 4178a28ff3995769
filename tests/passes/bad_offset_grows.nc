; A bad twin of die_three_passes: the last skim's H003 (0.150 mm) is larger than the skim before
; it (H002, 0.110 mm), so it runs outside the path already cut. A warning at its first move.
; expect exit: 0
; expect diagnostic: 24 K0611
; expect: pass 3: lines
H001 = +000000.1800;
H002 = +000000.1100;
H003 = +000000.1500;
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
