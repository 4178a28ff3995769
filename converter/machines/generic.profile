# Kerf machine profile (docs/machines.md): key = value lines; '#' at the start of a line is a
# comment. Copy it, change what your machine does differently, and read programs with
# `kerf check part.nc --machine my.profile`.
name = generic
summary = ISO 6983 wire programs: the standard word set, conventions decided by the program's evidence
source = ISO 6983-1; LinuxCNC rs274ngc (the reference interpreter Kerf's arcs are tested against)
# I J: incremental unless every arc closes only another way (auto).
arc_centre = auto
# Integers without a decimal point: millimetres unless none has a point and the largest is above
# the threshold (then micrometres, as Chinese fast-wire ISO files write them).
integer_unit = auto
integer_threshold = 1000
# U V: decided by the words, then by the numbers (docs/taper.md).
uv_words = auto
semicolon = comment
upper_axes = uv
bare_g92 = error
legacy_taper_codes = no
corner_r = comma
max_taper = 30
uv_range = none
thickness = none
# The cutting-time estimate (docs/passes.md, "Cutting time"). Every number here is an assumption
# for brass wire of 0.25 mm in tool steel, not a machine's figure: set your machine's own.
# rough_rate: mm² of cut face a minute where the wire cuts full material (a rough cut, a cut-off);
# a rough cut's speed is this over the workpiece thickness. skim_speed: mm/min along a skim.
rough_rate = 100
skim_speed = 10
rapid_speed = 1000
thread_time = 30
feed = machine
