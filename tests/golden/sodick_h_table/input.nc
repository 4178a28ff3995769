(Sodick style: register table, condition lines, ';' block ends, N-label subprogram after M02)
H000 = +000000.0000;
H001 = +000000.1300;
C001 = 001 002 003 004;
G90 G92 X10. Y0;
C001;
G41 H001 G01 X5. Y0;
M98 P0010;
G40 G01 X10. Y0;
M02;
N0010;
G01 X5. Y10.;
G03 X-5. Y10. R5.;
G01 X-5. Y0;
X5. Y0;
M99;
