; 4:1: error: macro B statement: variables, loops and jumps (#, WHILE, IF, GOTO) are evaluated by the control, and Kerf does not run them (3 macro lines, on lines 4 to 8) [K0113]
O0001
G92 X0 Y0
WHILE[#1 LT 2]DO1
G01 X10.
Y10.
END1
GOTO 10
M30
