; 2:1: error: this call would run more than 20000000 blocks (9999 times a subprogram of 30000 blocks with its own calls), beyond the limit of 20000000 executed blocks: refused before it runs [K0507]
M98 P1 L9999
M02
O1
M98 P2 L9999
M99
O2
G91 G01 X0.001
M99
