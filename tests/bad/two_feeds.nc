; 2:15: error: word 'F' appears twice in one block [K0108]
G01 X10. F12. F13.
M02
