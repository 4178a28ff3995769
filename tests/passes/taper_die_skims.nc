; A die opening 20 x 20 mm, 20 mm thick, with 1 degree of clearance, cut in a rough cut and two
; skims from a start hole at its centre (taper-angle words, Fanuc/NCVC: G51 leans the wire to the
; left of travel, G52 to the right, T the angle; G92 I the thickness). The rough cut and the last
; skim run counter-clockwise under G41 and G51; the middle skim runs clockwise, so it takes G42
; and G52 to stay inside with the same lean.
; Kerf reads the registers but does not apply a wire offset to a 4-axis program (K0210, a
; warning): the passes are checked and timed on their programmed path, 100 mm each.
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 3 passes
; expect: pass 1: lines 21-28, G41 H001 = 0.180 mm, counter-clockwise, closes, 100.000 mm
; expect: pass 2: lines 30-37, G42 H002 = 0.110 mm, clockwise, closes, 100.000 mm
; expect: pass 3: lines 39-46, G41 H003 = 0.085 mm, counter-clockwise, closes, 100.000 mm
; expect: wire slope max 1.414
; expect diagnostic: 21 K0210
; expect diagnostic: 26 K0614
H001 = +000000.1800
H002 = +000000.1100
H003 = +000000.0850
G90 G92 X0 Y0 I20. J0
G51 T1.
G41 H001 G01 X10. Y0
Y10.
X-10.
Y-10.
X10.
Y0
G50
G40 G01 X0 Y0
G52 T1.
G42 H002 G01 X10. Y0
Y-10.
X-10.
Y10.
X10.
Y0
G50
G40 G01 X0 Y0
G51 T1.
G41 H003 G01 X10. Y0
Y10.
X-10.
Y-10.
X10.
Y0
G50
G40 G01 X0 Y0
M02
