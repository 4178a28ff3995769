; A punch 30 x 20 mm with R5 corners on a Fanuc-style wire control: D registers from the
; machine's table (--offsets fanuc.offsets), the start hole 5 mm left of the left side's middle,
; a rough cut clockwise under G41 D1 (left of a clockwise contour: outside, a punch), a skim
; reversed under G42 D2 and a second skim clockwise again under G41 D3; I J incremental. Each pass
; closes the contour, so the rough cut cuts the punch free while skims follow: K0612 says to leave
; a tab (a shop that holds the punch by other means, a magnet, can silence it with -Wno-K0612).
; By hand, pass k at offset d: the straight sides 10 + 20 + 10 + 20 = 60, the four corners a
; circle of 5 + d, the lead-in and lead-out 5 - d each: 60 + 2 pi (5 + d) + 2 (5 - d):
; 102.101, 101.887 and 101.844 mm.
; options: --offsets fanuc.offsets
; expect exit: 0
; expect: contour 1 from (-5.000, 10.000): 3 passes
; expect: G41 D001 = 0.160 mm, clockwise, closes, 102.101 mm
; expect: G42 D002 = 0.110 mm, counter-clockwise, closes, 101.887 mm
; expect: G41 D003 = 0.100 mm, clockwise, closes, 101.844 mm
; expect diagnostic: 27 K0612
G90 G92 X-5. Y10.
G41 D1 G01 X0 Y10.
Y15.
G02 X5. Y20. I5. J0
G01 X25.
G02 X30. Y15. I0 J-5.
G01 Y5.
G02 X25. Y0 I-5. J0
G01 X5.
G02 X0 Y5. I0 J5.
G01 Y10.
G40 G01 X-5. Y10.
G42 D2 G01 X0 Y10.
Y5.
G03 X5. Y0 I5. J0
G01 X25.
G03 X30. Y5. I0 J5.
G01 Y15.
G03 X25. Y20. I-5. J0
G01 X5.
G03 X0 Y15. I0 J-5.
G01 Y10.
G40 G01 X-5. Y10.
G41 D3 G01 X0 Y10.
Y15.
G02 X5. Y20. I5. J0
G01 X25.
G02 X30. Y15. I0 J-5.
G01 Y5.
G02 X25. Y0 I-5. J0
G01 X5.
G02 X0 Y5. I0 J5.
G01 Y10.
G40 G01 X-5. Y10.
M30
