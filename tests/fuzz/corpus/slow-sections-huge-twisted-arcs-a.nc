; 2 both R and I/J:7]
G02 X10* Yh R and I/0 I5. J0 R5.M04 X. Y0 I5. J0 :20: ezror< arc0 I5. Jg0 „5.
M02 ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿG82 G92 X115000 Y-1Ð
(Kerf sample: re the last one ended.)
(The wir??????????????????????????????????????.8 (Entry Line. Set me eM.0 M0in mm.)
O0.
M003
N10 G20 G91 G17
N20 01 X0.25J0 R5.
G91 G92 X\115000 Y-9ÐË00
G0uuuuuuuuuuuuuuuuuuuuuuu0
G03 X-100 Y-80200 I0 J-40100
G01 X0 Y-400050100 J-100
G01 X-54900 Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuŠuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu
G00 X10. Y1
X4.
M U0 V0
G1 X0.010 Y0 G1 U0.011 V0i94 ÿX00 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X70200 Y0
G: the fil2e contains NUL bytes: i.
M02-40000900 J100
G01 X70200 Y0
G01 X0 Y50100
G01 X9900 Y0
U0X-100 Y-80200 I0 J-40100
G01 X0 Y-400050100 J-100
G01 X-54900 Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuŠuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu
G00 X10. Y1
X4.
M U0 V0
G1 X0.010 Q0 G1 U0.011 V0i94 ÿX00 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X70200 Y0
G: the fil2e contains NUL bytes: i.
M02-40000900 J10M02 ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿG82 G92 X115000 Y-1Ð
(Kerf sample: re the last one ended.)
(The wir??????????????????????????????????????.8 (Entry Line. Set me eM.0 M0in J10M02 ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿG82 G92 X115000 Y-1Ð
(Kerf sample: re the last one ended.)
(The wir??????????????????????????????????????.8 (Entry Line. Set me eM.0 M0in mm.)
O0.
M003
N10 G20 G91 G17
N20 01 X0.25J0 R5.
G91 G92 X\115000 Y-9ÐË00
G0uuuuuuuuuuuuuuuuuuuuuuu0
G03 X-100 Y-80200 I0 J-40100
G01 X0 Y-400050100 J-100
G01 X-54900 Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuŠuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu
G00 X10. Y1
X4.
M U0 V0
G1 X0.010 Y0 G1 U0.011 V0i94 ÿX00 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X70200 Y0
G: the fil2e contains NUL bytes: i.
M02-40000900 J100
G01 X70200 Y0
G01 X0 Y50100
G01 X9900 Y0
U0X-100 Y-80200 I0 J-40100
G01 X0 Y-400050100 J-100
G01 X-54900 Yuuuuuuuuuuuuu; 2:1: euuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuruuuuuuuuuuuuuuŠuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuuu
G00 X10. Y1
X4.
M U0 V0
G1 X0.010 Q0 G1 U0.011 V0i94 ÿX00 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X70200 Y0
G: the fil2e contains NUL bytes: i.
M02-40000900 J100
G01 X70200 Y0
G01 X0 Y50100
G01 X9900 Y0
U0I-50100 J-100
G01 X-sodic Y0
G03 X-100 Y-40100 I0 J-40100
G01 X0 Y-4.000
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I30 Y00
G02 X10. Y14X
.7
M10G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.7
M101 P2001ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ
G01 X9900 Y0
U0I-50100 J-100
G01 X-sodic Y0
G03 X-100 Y-40100 I0 J-40100
G01 X0 Y-4.000
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I30 Y00
G02 X10. Y14X
.7
M10G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.7
M101 P2001ÿÿÿÿÿ0200 Y0
G02 X79800 Y0 I39900 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I30 Y00
G02 X10. Y14X
.7
M10G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.7
M101 P2000ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ
G01 X9900 Y0
U0I-50100 J-100
G01 X-sodic Y0
G03 X-100 Y-40100 I0 J-40100
G01 X0 Y-4.000
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X702
G01 X60200 Y0
G02 X79800 Y0 I30 Y00
G02 X10. Y14X
.7
M10G92 X0
G94 ÿX0 Y00
G01 X10. Y1
X4.7
M101 P2001ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ X10. Y1
XW4.7
M101 P20
G92 X0
Guuuuuuuuuuuuu05uuuuuuuuuuuuuuuuuruuuuuu;G91 G92 X115000 Y-10000G03 X-100200 Y0 I-5ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ0100 J-100
G01 X-sodic Y0
G03 X-100 Y-80200 I0 J-4 0100
G65 X0 Y-40000
G0G91 G92 X115000 Y-00100
G01 X-9900 Y0
G01 X0 Y70100
G01 uuuX-5
G91 G92 X115000 Y-10000
G01 X-9900 Y0st deeper than 16 levels (recursion?) [K0503]
G90 G01 X0 Y0
M98 P1
M02
O1 M98 P10 Y0
G01 X05 1000Y
GG0I-50100 J-100
G01 X-sodic Y0
G03 X-100 Y-80200 I0 J-4 0100
G65 X0 Y-40000
G0G91 G92 1uuuuuuuu: 0e X01z.0