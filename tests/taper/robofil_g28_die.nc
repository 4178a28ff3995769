(Charmilles Robofil: a die 40 x 20 mm, 20 mm thick [--thickness 20], the wire leaning 3 degrees)
(right of travel - outwards - under G28: the sharp corners are tapered into arcs about each corner,)
(a cone whose apex is the corner on the program plane [the lower face]: on the upper face the)
(sides are offset 20 tan 3 and joined by arcs of that radius.)
G90 G92 X20. Y10.
G28
G52 A3.
G01 X20. Y0
X40.
Y20.
X0
Y0
X20.
G50
G01 X20. Y10.
M02
