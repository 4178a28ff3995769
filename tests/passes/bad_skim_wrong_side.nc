; A bad twin of die_three_passes: the skim G42 H002 runs counter-clockwise like the rough cut, so
; its wire runs outside the opening and cuts into the die plate. An error at its first move.
; expect exit: 1
; expect diagnostic: 17 K0610
; expect: pass 2: lines
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
Y10.;
X-10.;
Y-10.;
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
