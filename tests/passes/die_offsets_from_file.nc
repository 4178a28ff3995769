; die_three_passes without its H table: the registers are the machine's, given here by
; --offsets die.offsets. The pass table is the same as the table in the program gives.
; options: --offsets die.offsets
; expect exit: 0
; expect: pass 1: lines 9-15, G41 H001 = 0.180 mm, counter-clockwise, closes, 98.200 mm
; expect: pass 2: lines 16-22, G42 H002 = 0.110 mm, clockwise, closes, 98.900 mm
; expect: pass 3: lines 23-29, G41 H003 = 0.085 mm, counter-clockwise, closes, 99.150 mm
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
