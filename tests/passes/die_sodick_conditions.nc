; The three-pass die as a Sodick shop writes it: an H table, each pass under its own machining
; condition (C001 rough, C002 and C003 skims), two blocks on a line where ';' ends blocks. The
; shop's profile gives each condition's speed; the time by hand: 98.200 / 4 + 98.900 / 12 +
; 99.150 / 15 + 0.5 (one threading) = 24.550 + 8.242 + 6.610 + 0.500 = 39.902 min (the table rounds
; 24.55 down: it is 24.549999... in binary).
; options: --machine sodick_shop.profile
; expect exit: 0
; expect: pass 1: lines 17-23, G41 H001 = 0.180 mm, C001, counter-clockwise, closes, 98.200 mm, 24.5 min
; expect: pass 2: lines 24-30, G42 H002 = 0.110 mm, C002, clockwise, closes, 98.900 mm, 8.24 min
; expect: pass 3: lines 31-37, G41 H003 = 0.085 mm, C003, counter-clockwise, closes, 99.150 mm, 6.61 min
; expect: time 39.9 min (cutting 39.4, rapids 0.00, threading 0.50)
H001 = +000000.1800;
H002 = +000000.1100;
H003 = +000000.0850;
G90 G92 X0 Y0;
C001;
G41 H001 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y0;
G40 G01 X0 Y0; C002;
G42 H002 G01 X10. Y0;
Y-10.;
X-10.;
Y10.;
X10.;
Y0;
G40 G01 X0 Y0; c003;
G41 H003 G01 X10. Y0;
Y10.;
X-10.;
Y-10.;
X10.;
Y0;
G40 G01 X0 Y0;
M02;
