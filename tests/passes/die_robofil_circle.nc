; A round die opening of 16 mm on a Charmilles Robofil: centres written absolute (I J are the
; centre itself), a bare G92 at the start hole, D registers from the machine's table (here
; robofil.offsets), a rough cut counter-clockwise under G41 D1 and a reversed skim under G42 D2.
; Each pass: a line in from the centre, a full circle, a line back. By hand: 2 pi 7.830 + 2 x
; 7.830 = 64.857 mm, and 2 pi 7.875 + 2 x 7.875 = 65.230 mm.
; options: --machine robofil --offsets robofil.offsets
; expect exit: 0
; expect: contour 1 from (0.000, 0.000): 2 passes
; expect: pass 1: lines 14-16, G41 D001 = 0.170 mm, counter-clockwise, closes, 64.857 mm
; expect: pass 2: lines 18-20, G42 D002 = 0.125 mm, clockwise, closes, 65.230 mm
G92 X0 Y0
G90
G41 D1
G1 X8.000 Y0.000
G3 X8.000 Y0.000 I0.000 J0.000
G40 G1 X0.000 Y0.000
G42 D2
G1 X8.000 Y0.000
G2 X8.000 Y0.000 I0.000 J0.000
G40 G1 X0.000 Y0.000
M2
