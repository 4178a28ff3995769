%
(Kerf sample: a shop-floor style program, written the way many older posts write it.)
( - inch units [G20] and incremental coordinates [G91], sequence numbers on every block;)
( - bare G41: the wire offset is set at the controller, so Kerf warns that geometry and)
(   pictures show the programmed contour [record a value with --offset];)
( - a comb punch: the four teeth on the top edge are one subprogram, O100, called with a)
(   repeat count [M98 P100 L4]; in G91 each call starts where the last one ended.)
(The wire enters from a start hole at [-0.25, 0.25] in, cuts clockwise, and leaves the way)
(it came in. Try `kerf explain samples/inch_g91_bare_g41.nc`: every number is in mm.)
O0003
N10 G20 G91 G17
N20 G92 X-0.25 Y0.25
N30 G41 G01 X0.25 F0.08
N40 Y0.25
N50 M98 P100 L4
N60 G01 Y-0.5
N70 X-2.0
N80 Y0.25
N90 G40 X-0.25
N100 M30
O100 (one tooth: up, a half-round top, down, across to the next one)
N110 G01 Y0.25
N120 G02 X0.25 Y0 I0.125 J0
N130 G01 Y-0.25
N140 X0.25
N150 M99
%
