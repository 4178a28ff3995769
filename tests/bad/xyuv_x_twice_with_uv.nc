; 3:20: error: word 'X' appears twice in one block [K0108]
M101 P20
G1 X10. Y0 U10. V0 X11.
M2
