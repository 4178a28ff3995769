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
max_taper = 30
uv_range = none
thickness = none
