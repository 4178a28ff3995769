; 2 both R and I/J:7]
G02 X10. Yh R and I/0 I5. J0 R5.
M02 X. Y0 I5. J0 :20: ezror< arc0 I5. Jg0 „5.
M02 ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿG91 G92 X115000 Y-1Ð
(Kerf sample: re the last one ended.)
(The wire eM.0 M0in mm.)
O0.
M003
N10 G20 G91 G17
N20 01 X0.25J0 R5.
G91 G92 X115000 Y-1ÐË00
G0uuuuuuuuuuuuuuuuuuuuuuu0
G03 X-100 Y-80200 I0 J-40100
G01 X0 Y-400050100 J-100
G01 X-54900 Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuŠuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu
G01 X10. Y1
X4.
M U0 V0
G1 X0.010 Y0 G1 U0.011 V0i94 ÿX0 Y00
G01 X10. Y1
X4.7
M10G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.7
M101 P2001 X10. Y1
X4.7
M101 P20
G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.
M U0 V0
Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuu05uuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuuuu: 0e1z.0