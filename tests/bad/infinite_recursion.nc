; 5:4: error: subprogram calls nest deeper than 16 levels (recursion?) [K0503]
G90 G01 X0 Y0
M98 P1
M02
O1 M98 P1
M99
