; 2:1: error: this sodick-colon program gives no heights for its planes, and a taper needs them [K0217]
G01 X1. Y1. : G01 X2. Y2.
M02
