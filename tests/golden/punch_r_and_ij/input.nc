%
(Kerf sample: a punch outline that uses both ways of programming an arc.)
( - corners R5 by radius R, the top notch by centre I J [incremental: centre - start];)
( - a 70 x 40 mm plate profile with a 10 mm semicircular notch in the top edge;)
( - the wire enters from a start hole at [-5, 20], cuts clockwise, and leaves the way it came.)
(Compare the two arc forms in `kerf explain samples/punch_outline.nc`.)
O0002
G90 G21 G17
G92 X-5. Y20.
G01 X0 Y20. F3.
Y35.
G02 X5. Y40. R5.
G01 X25.
G03 X45. Y40. I10. J0 (notch, counter-clockwise seen from above: it dips into the part)
G01 X65.
G02 X70. Y35. R5.
G01 Y5.
G02 X65. Y0 I-5. J0
G01 X5.
G02 X0 Y5. R5.
G01 Y20.
X-5.
M30
%
