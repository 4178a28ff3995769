; 2:1: error: unknown G code G05 [K0201]
G05 X1.
M02
