; A punch 20 x 20 mm cut from a start hole outside it: the rough cut (G41, clockwise: the wire
; outside) closes the contour, so the punch falls before the skim G42 H002 runs. A warning at the
; rough cut's last move along the contour.
; expect exit: 0
; expect diagnostic: 15 K0612
; expect: pass 1: lines
H001 = +000000.1800;
H002 = +000000.1100;
G90 G92 X-15. Y0;
G41 H001 G01 X-10. Y0;
Y10.;
X10.;
Y-10.;
X-10.;
Y0;
G40 G01 X-15. Y0;
G42 H002 G01 X-10. Y0;
Y-10.;
X10.;
Y10.;
X-10.;
Y0;
G40 G01 X-15. Y0;
M02;
