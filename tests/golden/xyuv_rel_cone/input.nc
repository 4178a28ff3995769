(xyuv-rel, NCVC words: a cone frustum, R10 below and R8 20 mm above. U V are upper minus lower)
(at each block's end; K L the move from the lower arc's centre to the upper one's - 0 here.)
(G92 I J: thickness 20, program plane 0.)
%
G92 X0 Y0 I20. J0
G01 X10. Y0 U-2. V0
G03 X10. Y0 I-10. J0 U-2. V0 K0 L0
G01 X0 Y0 U0 V0
M02
%
