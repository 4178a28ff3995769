; 2:16: error: J counts along y, but y is 0: the line never moves that way, so J can never be reached [K0307]
B9900 B0 B9900 GY L1
DD
