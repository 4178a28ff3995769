; 3:5: error: dwell time P-5 is negative: a control waits for no less than nothing [K0228]
G92 X0 Y0
G04 P-5
G01 X10.
M02
