; 2:1: error: G18 selects a plane a wire machine cannot cut in; only G17 (XY) is allowed [K0204]
G18
M02
