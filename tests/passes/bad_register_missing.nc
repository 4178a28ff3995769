; A bad twin of die_offsets_from_file: the last skim names H004, which neither the program
; nor die.offsets gives. A warning at its G41 line; that pass is drawn on the programmed contour.
; options: --offsets die.offsets
; expect exit: 0
; expect diagnostic: 22 K0210
; expect: pass 3: lines 22-28, G41 H004 (offset at the machine)
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
G41 H004 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y0;
G40 G01 X0 Y0;
M02;
