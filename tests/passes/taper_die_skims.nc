; A die opening 20 x 20 mm, 20 mm thick, with 1 degree of clearance, cut in a rough cut and two
; skims from a start hole at its centre (taper-angle words, Fanuc/NCVC: G51 leans the wire to the
; left of travel, G52 to the right, T the angle; G92 I the thickness). The rough cut and the last
; skim run counter-clockwise under G41 and G51; the middle skim runs clockwise, so it takes G42
; and G52 to stay inside with the same lean.
; The wire offset applies on the program plane and the taper is taken from the offset path (K0901,
; a note; issue 55): on the program plane each pass is the 2-axis die's wire path, four sides of
; 20 - 2d and the lead-in and lead-out of 10 - d, 100 - 10d mm: 98.200, 98.900 and 99.150 mm.
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 3 passes
; expect: pass 1: lines 22-29, G41 H001 = 0.180 mm, counter-clockwise, closes, 98.200 mm
; expect: pass 2: lines 31-38, G42 H002 = 0.110 mm, clockwise, closes, 98.900 mm
; expect: pass 3: lines 40-47, G41 H003 = 0.085 mm, counter-clockwise, closes, 99.150 mm
; expect: wire slope max 1.414
; expect diagnostic: 22 K0901
; expect diagnostic: 27 K0614
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
