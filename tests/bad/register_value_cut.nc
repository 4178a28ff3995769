; 3:5: error: 'XH111 + H112' (a register value): the wire's position after it is known only at the machine; the 2 moves on lines 3 to 4 (2 cut) cannot be drawn or checked; line 4 gives it again [K0233]
G92 X0 Y0
G01 XH111 + H112 Y0
X20. Y10.
G92 X0 Y0
G01 X5.
M02
