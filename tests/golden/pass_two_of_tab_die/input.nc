; The die with a tab and a cut-off (tests/passes/die_tab_cut_off.nc), converted with --pass 2:
; the skim alone (G42 H002, clockwise), from the start hole and back.
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
