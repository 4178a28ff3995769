; 2:8: error: repeat count L must be a whole number from 1 to 9999 [K0506]
M98 P1 L0
M02
O1
M99
