; The die with a tooth of die_tooth_skims_reversing.nc, its back skim under G41: the wire crosses
; to the part's side of the tooth and cuts into it (K0610 at the skim).
; options: --machine sodick
; expect exit: 1
; expect: pass 3: lines 28-33, G41 H003 = 0.085 mm, clockwise
; expect diagnostic: 28 K0610
H001 = +000000.1800
H002 = +000000.1100
H003 = +000000.0850
G90 G92 X0 Y0
G41 H001 G01 X10. Y0
Y10.
X2.
Y4.
X-2.
Y10.
X-10.
Y-10.
X10.
Y0
G40 G01 X0 Y0
G41 H002 G01 X6. Y10.
X2.
Y4.
X-2.
Y10.
X-6.
G41 H003 G01 X-2.
Y4.
X2.
Y10.
X6.
G40 G01 X0 Y0
M02
