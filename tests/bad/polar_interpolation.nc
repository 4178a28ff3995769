; 2:1: error: G12.1 (polar coordinate interpolation) is not supported yet [K0201]
G12.1
M02
