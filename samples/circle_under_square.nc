(Different-shape part: a circle R10 on the lower plane, a square with its corners on that)
(circle on the upper plane, 30 mm above. Each quarter arc below is paired with one side above.)
(Dialect xyuv-abs, as the papayaved/cnc3 controller writes it: X Y the lower contour, U V the)
(upper contour in the same frame, each side with its own motion word. M101 P is the thickness;)
(M100 P Q the guide distances, which Kerf records but does not need.)
(Expected: kerf check says ok; the slope is 0 at the square's corners and 5.6 degrees mid-side.)
%
M100 P375 Q117
M101 P30
G92 X15. Y0 U15. V0
G1 X10. Y0 G1 U10. V0 F1.5
G3 X0 Y10. I-10. J0 G1 U0 V10.
G3 X-10. Y0 I0 J-10. G1 U-10. V0
G3 X0 Y-10. I10. J0 G1 U0 V-10.
G3 X10. Y0 I0 J10. G1 U10. V0
G1 X15. Y0 G1 U15. V0
M2
%
