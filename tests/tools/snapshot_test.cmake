# One snapshot test: render with kerf (headless, DISPLAY unset) or take a window screenshot, then
# compare with the baseline by SSIM error (tests/image/ssim.h).
#   cmake -DKERF=... -DCOMPARE=... -DBASELINE=... -DOUTPUT=... -DTHRESHOLD=... -DEXIT=0|1 -DMODE=render|window
#         -DXVFB=... -DARGS="a;b;c" -P snapshot_test.cmake
# KERF_UPDATE_SNAPSHOTS=1 in the environment accepts the new picture as the baseline
# (compare_snapshot.cmake).
# On failure the rendered picture (OUTPUT) and a diff image (OUTPUT without .png + .diff.png) stay.
get_filename_component(out_dir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
string(REGEX REPLACE "\\.png$" ".diff.png" diff "${OUTPUT}")
file(REMOVE "${OUTPUT}" "${diff}")
if(MODE STREQUAL "window")
  # Our own auth file: xvfb-run's temporary folder sometimes fails its clean-up (exit 5).
  execute_process(COMMAND ${XVFB} -a -f "${out_dir}/xauthority" -s "-screen 0 1280x1024x24" ${KERF} view ${ARGS}
                          --screenshot ${OUTPUT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
else()
  # lsan_retry.sh: the ASan build's LeakSanitizer tracer sometimes crashes at exit (the script says when).
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
                          sh ${CMAKE_CURRENT_LIST_DIR}/lsan_retry.sh ${KERF} render ${ARGS} -o ${OUTPUT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
# The verdict is pinned: 0 the part has no errors, 1 it has (the picture shows them).
if(NOT EXISTS "${OUTPUT}" OR NOT rc STREQUAL "${EXIT}")
  message(FATAL_ERROR "kerf ${MODE} gave exit ${rc}, expected ${EXIT}:\n${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/compare_snapshot.cmake)
kerf_compare_snapshot("${COMPARE}" "${BASELINE}" "${OUTPUT}" "${THRESHOLD}" "${diff}")
file(REMOVE "${OUTPUT}")
