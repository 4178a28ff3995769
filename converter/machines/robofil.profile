# Kerf machine profile (docs/machines.md).
name = robofil
summary = Charmilles Robofil (GF Machining Solutions): absolute arc centres, micrometre integers, G60/G38/G39/M28
source = real Robofil programs in Insignifi4nt/wireedm-gcode-parser (testing_gcode_files, artifacts/robofil-v2), including a post its authors cut on a Robofil 100
# I J are the centre itself: G03X-8500Y0I0J0 is an arc about the origin.
arc_centre = absolute
# Files write either decimal millimetres or integers in micrometres (X6500): with no decimal point
# anywhere, integers are micrometres.
integer_unit = auto
integer_threshold = 0
uv_words = auto
semicolon = comment
upper_axes = uv
# A bare G92 makes the current position the origin (PinZ15, 2K-Filera open with it).
bare_g92 = origin
legacy_taper_codes = no
corner_r = comma
max_taper = 30
uv_range = none
thickness = none
# What the real programs write around each contour. Their exact meaning is not published; none
# moves the wire, and the programs cut the part they draw.
code G60 = harmless: written at the start of every program and contour (a corner or start-hole function); meaning not modelled [assumed: no effect on the path]
code G38 = harmless: written after G60 before the wire offset starts; meaning not modelled [assumed: no effect on the path]
code G39 = harmless: written before G40 between contours (the post's compensation cycle); meaning not modelled [assumed: no effect on the path]
# Taper corners (Autodesk FeatureCAM's wire taper options for a Charmilles machine: "Rounded" is
# G28, "ISO" is G29). Not the standard G28 (return home): on a Charmilles they choose the corners.
code G28 = corner-rounded: taper corners rounded: sharp corners tapered into arcs about the corner, arcs into cones [sourced: FeatureCAM help, medium]
code G29 = corner-cylindrical: ISO taper corners: sharp corners kept sharp, arcs tapered into cylinders [sourced: FeatureCAM help, medium]
code M28 = harmless: written after G60 at the start of a program; meaning not modelled [assumed: no effect on the path]
# Writing for a Robofil (kerf convert --to iso --for robofil, kerf cam --machine robofil): the
# layout of the post whose output cut a real part on a Robofil 100 (wireedm-gcode-parser's
# z39RobofilPost acceptance test): mm with 3 decimals, G1/G2/G3, no comment, G92 G60 G38 then the
# offset as G41/G42 D0 (the machine's table) then G90; G39 G40 to cancel between contours; M02
# last, with no G40; CRLF. Older real programs write micrometre integers (write_unit = um reads
# and writes those too); both are read.
write_unit = mm
write_decimals = 3
write_comment = no
write_g = G1
write_start = G92 X{x} Y{y} | G60 | G38 | {offset} | G90
write_offset = {g} D0
write_cancel = G39 | G40
write_end = M02
line_end = crlf
