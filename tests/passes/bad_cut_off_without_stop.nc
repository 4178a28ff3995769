; A bad twin of die_tab_cut_off: no stop (M00, M01) between the skim and the cut-off through the
; tab, so the slug falls with nobody to secure it. A warning at the cut-off's first move.
; expect exit: 0
; expect diagnostic: 23 K0613
; expect: pass 3: lines
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
G41 H001 G01 X10. Y-2.;
Y0;
G40 G01 X0 Y0;
M02;
