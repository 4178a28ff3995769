(Output through a custom profile: micrometre integers, incremental, numbered, with header)
G90 G92 X0 Y0
G01 X10.0004 Y0
G03 X0 Y10.0004 R10.0004
G01 X0 Y0
M02
