(Bad part: the taper [G52, 3 degrees] starts on an arc. NC controls refuse it: the wire cannot)
(begin to lean while it follows a circle. Start the taper on a straight lead-in instead.)
(taper-angle, Sodick words: A the angle; 20 mm thick.)
(Expect: error K0219)
%
G92 X10. Y0 I20.
G52 A3.
G03 X-10. Y0 I-10. J0
G03 X10. Y0 I10. J0
G50
G01 X12. Y0
M02
%
