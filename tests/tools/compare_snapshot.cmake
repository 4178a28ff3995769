# The one comparison of a picture with its baseline by SSIM error (tests/image/ssim.h), included by
# snapshot_test.cmake (kerf render and kerf view) and browser_test.cmake (pages in Chromium).
# KERF_UPDATE_SNAPSHOTS=1 in the environment accepts the new picture as the baseline.
#   kerf_compare_snapshot(COMPARE BASELINE OUTPUT THRESHOLD DIFF): fails the test, naming the
#   picture and its diff image, when they differ by more than THRESHOLD.
function(kerf_compare_snapshot compare baseline output threshold diff)
  if(DEFINED ENV{KERF_UPDATE_SNAPSHOTS} AND NOT "$ENV{KERF_UPDATE_SNAPSHOTS}" STREQUAL "0")
    file(COPY_FILE "${output}" "${baseline}")
    message(STATUS "snapshot baseline updated: ${baseline}")
    return()
  endif()
  if(NOT EXISTS "${baseline}")
    message(FATAL_ERROR "no baseline ${baseline}: look at ${output} and accept it with KERF_UPDATE_SNAPSHOTS=1")
  endif()
  execute_process(COMMAND ${compare} ${baseline} ${output} --threshold ${threshold} --diff ${diff}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "snapshot differs from ${baseline}: ${out}${err}taken: ${output}\ndiff: ${diff}")
  endif()
endfunction()
