; 2:14: error: Z beside U and no V anywhere in the program: the second plane's axes may be named U Z [K0235]
G92 X0 Y0 U0 Z0
G01 X10 U10 Y0 Z0
X10 U10 Y10 Z10
M02
