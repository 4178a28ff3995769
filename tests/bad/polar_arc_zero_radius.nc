; 4:10: error: arc radius is zero [K0305]
G112
G1 X0 C0
G3 X1 C0 R0
G113
M30
