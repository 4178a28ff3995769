# Snapshot tests: one line each (cmake/KerfSnapshotTest.cmake). Baselines are tests/snapshots/<name>.png;
# KERF_UPDATE_SNAPSHOTS=1 ctest -L snapshot rewrites them (look at each before committing).
set(s --size 320x240)
# Every sample kind, iso.
kerf_snapshot_test(NAME sector_r40_iso ARGS samples/sector_r40.nc ${s})
kerf_snapshot_test(NAME punch_outline_iso ARGS samples/punch_outline.nc ${s})
kerf_snapshot_test(NAME inch_g91_iso ARGS samples/inch_g91_bare_g41.nc ${s})
kerf_snapshot_test(NAME taper_punch_iso ARGS samples/taper_punch_2deg.nc ${s})
kerf_snapshot_test(NAME circle_under_square_iso ARGS samples/circle_under_square.nc ${s})
kerf_snapshot_test(NAME sodick_colon_iso ARGS samples/sodick_colon_bulge.nc ${s})
# Every view.
kerf_snapshot_test(NAME punch_outline_top ARGS samples/punch_outline.nc ${s} --view top)
kerf_snapshot_test(NAME punch_outline_front ARGS samples/punch_outline.nc ${s} --view front)
kerf_snapshot_test(NAME punch_outline_side ARGS samples/punch_outline.nc ${s} --view side)
kerf_snapshot_test(NAME taper_punch_top ARGS samples/taper_punch_2deg.nc ${s} --view top)
# Colour by slope, with its legend.
kerf_snapshot_test(NAME taper_punch_slope ARGS samples/taper_punch_2deg.nc ${s} --color-by slope)
kerf_snapshot_test(NAME circle_under_square_slope ARGS samples/circle_under_square.nc ${s} --color-by slope --view front)
# Colour by pass, with its legend (below the title): a die and a punch, each with a tab and its cut-off.
kerf_snapshot_test(NAME die_tab_cut_off_passes ARGS tests/passes/die_tab_cut_off.nc ${s} --color-by pass)
kerf_snapshot_test(NAME punch_tab_cut_off_passes ARGS tests/passes/punch_tab_cut_off.nc ${s} --color-by pass)
# A taper die cut with G41/G42 in a rough cut and two skims: three passes on both planes (issue 55).
kerf_snapshot_test(NAME taper_die_skims_passes ARGS tests/passes/taper_die_skims.nc ${s} --color-by pass)
# The wire at its guides (--show guides): cnc3's calibration cone, its guides from M100 P Q.
kerf_snapshot_test(NAME cnc3_cone_guides ARGS tests/taper/cnc3_cone_guides.nc ${s} --show guides)
# Findings highlighted: a 2-axis crossing, and taper faults.
kerf_snapshot_test(NAME path_crosses_highlight EXIT 1 ARGS tests/bad/path_crosses_itself.nc ${s} --highlight-findings --view top)
kerf_snapshot_test(NAME too_steep_highlight EXIT 1 ARGS samples/bad/too_steep.nc ${s} --highlight-findings --color-by slope)
kerf_snapshot_test(NAME surface_meets_itself_highlight EXIT 1 ARGS samples/bad/surface_meets_itself.nc ${s} --highlight-findings)
kerf_snapshot_test(NAME wire_crossing_highlight EXIT 1 ARGS samples/bad/wire_crossing.nc ${s} --highlight-findings)
# Nine errors and warnings: labels that would cover one another are left out and counted ("+3 more").
kerf_snapshot_test(NAME offset_collapses_more_findings EXIT 1
                   ARGS samples/bad/offset_collapses.nc --size 480x360 --highlight-findings)
# The wire path beside what it was made from (dashed): a drawing's contours, a G41 program as written.
kerf_snapshot_test(NAME plate_dxf_wire_top ARGS samples/plate.dxf ${s} --offset 1 --side outside --view top)
kerf_snapshot_test(NAME g41_applied_top ARGS samples/inch_g91_bare_g41.nc ${s} --offset 1 --view top)
# A program against its drawing (issue 43): the part edge coloured by its deviation, the legend in um
# with the tolerance marked, the worst point marked, the drawing dashed beside it.
kerf_snapshot_test(NAME plate_deviation_top EXIT 1
                   ARGS tests/drawing/plate_radius_off.nc --size 480x360 --drawing samples/plate.dxf
                        --color-by deviation --view top)
# A taper part's upper plane turned 1 degree against the drawing of both planes: the lower edge
# within tolerance (blue), the upper edge red, the worst marked on the upper plane.
kerf_snapshot_test(NAME taper_upper_deviation EXIT 1
                   ARGS tests/drawing/taper_upper_turned.nc --size 480x360 --thickness 20
                        --drawing tests/drawing/taper_square.dxf --drawing-layer LOWER --drawing-upper-layer UPPER
                        --color-by deviation)
# Teaching (issue 44, docs/teaching.md): a block's construction with its words and modes.
# Line 15 of the seed's sector, G03 X0 Y40. R40.: the chord, its bisector, both candidate centres.
kerf_snapshot_test(NAME explain_r_arc ARGS samples/sector_r40.nc --size 640x480 --explain-line 15 --step 5 --view top)
# An I J arc: the vector from the start to the centre.
kerf_snapshot_test(NAME explain_ij_arc ARGS samples/punch_outline.nc --size 640x480 --explain-line 14 --step 2 --view top)
# A taper move: both planes' arcs, the wire at both ends with its slope.
kerf_snapshot_test(NAME explain_taper_move ARGS samples/taper_punch_2deg.nc --size 640x480 --explain-line 14)
# A wire-offset move: the programmed arc dashed, the wire's, the offset between them (inch, G91).
kerf_snapshot_test(NAME explain_offset_move
                   ARGS samples/inch_g91_bare_g41.nc --size 640x480 --offset 0.1 --explain-line 23 --view top)
# The headless back ends must agree: the same picture through EGL.
kerf_snapshot_test(NAME taper_punch_iso_egl ARGS samples/taper_punch_2deg.nc ${s} --backend egl)

# The window under xvfb-run: text panel, 3D view, findings panel; a block selected, the wire shown.
if(KERF_XVFB_RUN)
  kerf_snapshot_test(NAME view_taper_punch WINDOW
                     ARGS samples/taper_punch_2deg.nc --size 900x560 --frames 4 --line 16 --colour-by slope)
  kerf_snapshot_test(NAME view_punch_playback WINDOW
                     ARGS samples/punch_outline.nc --size 900x560 --frames 4 --playback 0.4)
  # --line with --playback: the block asked for stays selected (line 14), the wire is drawn halfway.
  kerf_snapshot_test(NAME view_line_with_playback WINDOW
                     ARGS samples/taper_punch_2deg.nc --size 900x560 --frames 4 --line 14 --playback 0.5)
  # A program cut in three passes: the pass list, coloured by pass, the skim's block selected.
  kerf_snapshot_test(NAME view_passes WINDOW
                     ARGS tests/passes/die_tab_cut_off.nc --size 900x560 --frames 4 --colour-by pass --line 20)
  # A program against its drawing (issue 43): the part edge by deviation, the elements out of
  # tolerance listed, the worst one's block selected.
  kerf_snapshot_test(NAME view_plate_deviation WINDOW EXIT 1
                     ARGS tests/drawing/plate_radius_off.nc --size 900x560 --frames 4 --drawing samples/plate.dxf
                          --colour-by deviation --line 5)
  # Teaching (issue 44): the selected block's construction in the view, its words and modes in the
  # block panel; the same four blocks as the pictures (explain_*).
  kerf_snapshot_test(NAME view_explain_r_arc WINDOW
                     ARGS samples/sector_r40.nc --size 1100x700 --frames 4 --line 15 --step 5)
  kerf_snapshot_test(NAME view_explain_ij_arc WINDOW
                     ARGS samples/punch_outline.nc --size 1100x700 --frames 4 --line 14 --step 2)
  kerf_snapshot_test(NAME view_explain_taper_move WINDOW
                     ARGS samples/taper_punch_2deg.nc --size 1100x700 --frames 4 --line 14)
  kerf_snapshot_test(NAME view_explain_offset_move WINDOW
                     ARGS samples/inch_g91_bare_g41.nc --size 1100x700 --frames 4 --offset 0.1 --line 23)
else()
  message(WARNING "xvfb-run (package xvfb) not found: the window snapshot tests are not built")
endif()
