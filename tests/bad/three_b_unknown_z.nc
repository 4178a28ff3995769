; 2:19: error: unknown Z 'L5': a 3B record ends with L1-L4, SR1-SR4 or NR1-NR4 [K0120]
B9900 B0 B9900 GX L5
DD
