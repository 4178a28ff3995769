# Kerf machine profile (docs/machines.md).
name = sodick
summary = Sodick wire EDM: condition and offset tables, `;` ends blocks, QAIC corner control, TP/TN, G140-G142, G51/G52 A
source = programs written by Meconer's SodickDXFCoder (codingPkg/TBCoder.java and its header templates) and Sodick programs from the same shop's tools
arc_centre = incremental
integer_unit = mm
integer_threshold = 1000
# Taper programs are taper-angle (G51/G52 with A) or sodick-colon (`lower : upper`); U V do not occur.
uv_words = auto
semicolon = end-of-block
upper_axes = uv
bare_g92 = error
legacy_taper_codes = no
corner_r = comma
max_taper = 30
uv_range = none
thickness = none
code A = harmless: the taper angle; it leans the wire only under G51/G52 (A0 with no G51 is no taper)
code C = condition: machining condition number: selects a row of the condition table (C000 = ...)
code QAIC = harmless: corner control (feed and power at corners, its arguments as written); no change to the programmed path [assumed]
code G29 = harmless: written after G92 before the cut; meaning not modelled [assumed: no effect on the path]
code G149 = harmless: written after the cut; meaning not modelled [assumed: no effect on the path]
code G249 = harmless: written after the cut with G149; meaning not modelled [assumed: no effect on the path]
code G80 = position: contact sensing: the wire moves along the axis given as X+ X- Y+ Y- until it touches the work
code G83 = no-motion: stores the current position of the axis in the register the word names (G83 Y101: Y into H101)
code T84 = harmless: auxiliary function written before the cut; meaning not modelled (flushing on, on Sodick controls) [unsure]
code T85 = harmless: auxiliary function written after the cut; meaning not modelled (flushing off) [unsure]
code T94 = harmless: auxiliary function written before the cut; meaning not modelled [unsure]
code M199 = program-end: ends the program in place of M02 in SodickDXFCoder output
# Writing for a Sodick (kerf convert --to iso --for sodick): `;` ends each block (semicolon),
# a taper program as `lower : upper` with TN/TP heights.
write_taper = sodick-colon
