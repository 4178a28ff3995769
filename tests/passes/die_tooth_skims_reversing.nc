; A die 20 x 20 mm with a tooth of the part reaching into it (4 mm wide, 6 mm deep), roughed
; counter-clockwise under G41, then the tooth skimmed forward with G41 and back with G42, the
; skims reversing with no G40 between (as shops skim a stretch that needs it). Both skims keep the
; wire inside the die: G41 forward and G42 backward are the same side of each element. Their
; direction is the way they travel along the rough cut: over the tooth the area a stretch and its
; chord enclose turns the other way, which used to say "clockwise" for the forward skim and report
; the error K0610 at both (issue 55).
; options: --machine sodick
; expect exit: 0
; expect: pass 1: lines 17-27, G41 H001 = 0.180 mm, counter-clockwise, closes
; expect: pass 2: lines 28-34, G41 H002 = 0.110 mm, counter-clockwise, leaves a tab
; expect: pass 3: lines 34-39, G42 H003 = 0.085 mm, clockwise, leaves a tab
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
G42 H003 G01 X-2.
Y4.
X2.
Y10.
X6.
G40 G01 X0 Y0
M02
