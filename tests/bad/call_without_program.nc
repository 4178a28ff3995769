; 2:1: error: M98 needs the subprogram number in P [K0501]
M98
M02
