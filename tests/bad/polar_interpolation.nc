; 2:1: error: G12.1 (polar coordinate interpolation, X and C words) is not supported yet: no G13.1 follows it [K0236]
G12.1
M02
