; 2:20: error: arc has both R and I/J: give one of them [K0207]
G02 X10. Y0 I5. J0 R5.
M02
