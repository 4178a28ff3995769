; 2:1: error: coordinates without a motion command [K0212]
X10. Y10.
M02
