# Kerf machine profile (docs/machines.md).
name = cnc3
summary = Meatec / papayaved cnc3 wire EDM: two motions in one block, M100/M101 taper geometry, M40-M110 machine functions
source = papayaved/cnc3 editor help (Help/edm/en/editor.html) and its G-code reader (gcode.cpp, GCode::getSettings, getContours)
# "Cx, Cy - an incremental position of the arc center ... based on current coordinates"
arc_centre = incremental
integer_unit = mm
integer_threshold = 1000
# "The U, V coordinates are interpreted as an independent coordinate system, not as an offset to X, Y"
uv_words = xyuv-abs
semicolon = comment
upper_axes = uv
bare_g92 = error
# Before the codes were renumbered, M106 P L Q H gave the guides and M107 P T the thickness
# (15831944/cnc3 gcode.cpp at 4ae9a321). A program whose M106 has both P and Q uses that numbering.
legacy_taper_codes = detect
corner_r = comma
max_taper = 30
uv_range = none
thickness = none
code M40 = harmless: pump on
code M41 = harmless: pump off
code M82 = harmless: wire drum on
code M83 = harmless: wire drum off
code M84 = harmless: high voltage on
code M85 = harmless: high voltage off
code M100 = guides: P the distance between the roller axes L, Q the lower roller axis to the workpiece's bottom H (mm)
code M101 = thickness: P the workpiece thickness T (mm): the UV plane is the workpiece's top, the XY plane its bottom
code M102 = harmless: P the rollers' diameter plus half the wire, Q whether the rollers tilt
code M103 = harmless: P the rollers' plane (0 XZ, 1 YZ), Q the side of the wire on the rollers
code M105 = harmless: P the wire drum speed, 1 to 7
code M106 = harmless: P the cutting current, 0 to 11
code M107 = harmless: P the generator's pulse width, Q its duty ratio
code M108 = harmless: low cutting voltage (finishing passes)
code M109 = harmless: normal cutting voltage
code M110 = harmless: P Q the voltage thresholds of feedback cutting
