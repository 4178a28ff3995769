(A hot-wire wing cut as foam cutter firmware writes it: the carriages X Y and U V homed as axes of)
(their own, a rotary table B homed and left alone. U V homed as axes are absolute carriages: the)
(program reads as xyuv-abs even where the numbers could not tell - issue 55; the homed B is a note.)
(Read with --thickness 300, the distance between the carriages.)
G21 G90
G28 X Y U V
G28 B
G01 X10. Y10. U60. V12. F100
G01 X30. Y10. U80. V12.
G01 X30. Y20. U80. V18.
G01 X10. Y10. U60. V12.
M2
