(Bad part: in one move the upper guide runs exactly against the lower one, so every position)
(of the wire passes through one point half-way up: the wire crosses its own path.)
(xyuv-abs, 30 mm thick; an open cut, so the part also stays attached [a warning].)
(Expect: error K0652)
%
M101 P30
G92 X0 Y0 U10. V0
G1 X10. Y0 G1 U0 V0
M2
%
