# Kerf machine profile (docs/machines.md).
name = linuxcnc
summary = LinuxCNC XYUV (hot wire, foam): U V move linearly during an XY arc, heights in AXIS comments, lower-case words
source = LinuxCNC configs/sim/axis/foam/foam.ngc and the rs274ngc canonical machine (extra axes move linearly with an arc, as Z does in a helix)
arc_centre = incremental
integer_unit = mm
integer_threshold = 1000
uv_words = xyuv-linuxcnc
semicolon = comment
upper_axes = uv
bare_g92 = error
legacy_taper_codes = no
corner_r = comma
# The two planes are independent carriages: no guide limits how far the wire leans. 60 degrees
# is a decision, not a machine limit: a wire leaning further is probably a program error.
max_taper = 60
uv_range = none
thickness = none
# A hot-wire cutter moves at the F the program gives (mm/min): the time estimate uses it. It
# threads no wire.
feed = speed
thread_time = 0
