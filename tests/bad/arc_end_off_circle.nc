; 2:13: error: arc end point is 4.000 mm off the circle through the start (limit 0.028 mm) [K0304]
G02 X10. Y0 I3. J0
M02
