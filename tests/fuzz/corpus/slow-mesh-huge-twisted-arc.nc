G91 G92 X115000 Y-10000
G01 X-9900 Y0
G01 X0 Y70100
G01 X-5
G91 G92 X115000 Y-10000
G01 X-9900 Y0
G01 X0 Y70100
G01 X-55000 Y0
G03 X-100200 Y0 I-50100 J-100
G01 X-54900 Y0
G03 ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿX-100 Y-80200 I0 J-40100
G01 X0 Y-40000
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X7020bprogram calls nest deeper than 16 levels (recursion?) [K0503]
G90 G01 Ø0 Y0
M98 P1
M0)2
O1 M98 P10 Y0
G01 X05 1000Y
GG01 X0 Y-40000
G01 X60200# Y0
G02 X79800 Y0 I39900 J100
G01 X70200 Y0
G01 X9705 Y0AutoCAD Binary DXF
 + H112' (a register value): the wire's position after it is known only at the machine; the 2 moves on lines 3 to 4 (2 cut) cannot be drawn or checked; line 4 gives it again [K0233]
00 P375 Q117
M101 P21
G92 X0 Y0 U0 V0
G1 X5 Y0 G1 U5 V0 F1.8 (Entry Line. Qet maximuuuuuuuuuruuuuuuuuuuu+uu
M00ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿX-100 Y-80200 I0 J-40100
G01 X0 Y-40000
G01 X60200 Y0
G02 X79800 Y0 I39900 J100
G01 X7020bprogram calls nest deeper than 16 levels (recursion?) [K0503]
G90 G01 Ø0 Y0
M98 P1
M0)2
O1 M98 P10 Y0
G01 X02 Y5010uŠuuuuuuuuuuuuuuuuuuu
G94uuuuerror: 3 Y0
M02'XH05 second ;de arr :#u0
G1 X0.010 Y0 G1 U0.011 V0i94 ÿX0 Y00
G01 X10cond ;de arr :#umober has a second ;decimal p20.00003]
G010.
X0 Y/
M: error: 3 Y0
M02'XH05 second ;decimal point [G83K01000

G3]
G010.
X0 Y0
M: error: 3 Y0
M021XH11cimal point [G83K0103]
G010.
X0 Y0
M: error: 3 Y 3 Y0
M021XH11cimal point [G81 3K0103]
G010.
X0 Y0
M: error: 3 Y 3 Y0
M021XH11cimal point [G83K0103]
G010.
X0 Y0
MX93K0103]
G010.
X0 Y0
M: error: 3 Y0
M021900 Y0
M0X2
H11
