; A punch 20 x 20 mm from a start hole outside it, as a shop holds it: the rough cut (G41,
; clockwise: the wire outside) and a skim (G42, counter-clockwise) each stop short of a 4 mm tab
; on its left side; a stop (M00) to secure the punch, then the cut-off through the tab.
; expect exit: 0
; expect: contour 1 from (-15.000, 0.000): 3 passes
; expect: pass 1: lines
; expect: pass 3: lines
H001 = +000000.1800;
H002 = +000000.1100;
G90 G92 X-15. Y0;
G41 H001 G01 X-10. Y2.;
Y10.;
X10.;
Y-10.;
X-10.;
Y-2.;
G40 G01 X-15. Y0;
G42 H002 G01 X-10. Y-2.;
Y-10.;
X10.;
Y10.;
X-10.;
Y2.;
G40 G01 X-15. Y0;
M00;
G41 H001 G01 X-10. Y-2.;
Y2.;
G40 G01 X-15. Y0;
M02;
