; 3:15: error: 'B' turns a rotary axis while the wire moves: Kerf does not model it, so this move cannot be checked [K0107]
G21 G90
G01 X10. Y10. B20. F100
M2
