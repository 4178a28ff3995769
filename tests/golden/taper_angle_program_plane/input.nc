(taper-angle with the program plane half-way up [NCVC G92 J]: the programmed square is the)
(section at z 10; the lower contour is offset one way, the upper the other. G52: lean right.)
%
G92 X0 Y-10. I20. J10.
G52 T3.
G01 X0 Y0
X10.
Y10.
X-10.
Y0
X0
G50
G01 Y-10.
M02
%
