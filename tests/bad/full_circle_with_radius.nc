; 2:11: error: arc ends where it starts, and R cannot describe a full circle [K0303]
G02 X0 Y0 R5.
M02
