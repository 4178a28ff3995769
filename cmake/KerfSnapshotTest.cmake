# Snapshot tests, one line each (in the manner of f3d's image tests):
#   kerf_snapshot_test(NAME <name> ARGS <kerf render arguments...> [THRESHOLD <t>] [EXIT <code>] [WINDOW])
# renders headlessly (or, with WINDOW, screenshots `kerf view` under xvfb-run) and compares with
# tests/snapshots/<name>.png by SSIM error (tests/image/ssim.h). Default threshold
# KERF_SNAPSHOT_THRESHOLD; every override says why in a comment next to it. EXIT pins the verdict
# kerf must give for the part (default 0: no errors; 1: the part has errors, drawn all the same).
set(KERF_SNAPSHOT_THRESHOLD 0.05 CACHE STRING "Default SSIM error threshold of the snapshot tests")
function(kerf_snapshot_test)
  cmake_parse_arguments(ARG "WINDOW" "NAME;THRESHOLD;EXIT" "ARGS" ${ARGN})
  if(NOT ARG_THRESHOLD)
    set(ARG_THRESHOLD ${KERF_SNAPSHOT_THRESHOLD})
  endif()
  if(NOT DEFINED ARG_EXIT)
    set(ARG_EXIT 0)
  endif()
  set(mode render)
  set(prefix snapshot)
  if(ARG_WINDOW)
    set(mode window)
    set(prefix window)
  endif()
  add_test(NAME ${prefix}.${ARG_NAME}
           COMMAND ${CMAKE_COMMAND} -DKERF=$<TARGET_FILE:kerf> -DCOMPARE=$<TARGET_FILE:kerf_image_compare>
                   -DBASELINE=${PROJECT_SOURCE_DIR}/tests/snapshots/${ARG_NAME}.png
                   -DOUTPUT=${CMAKE_BINARY_DIR}/tests/snapshots-out/${ARG_NAME}.png -DTHRESHOLD=${ARG_THRESHOLD} -DEXIT=${ARG_EXIT}
                   -DMODE=${mode} -DXVFB=${KERF_XVFB_RUN} "-DARGS=${ARG_ARGS}"
                   -P ${PROJECT_SOURCE_DIR}/tests/tools/snapshot_test.cmake
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set(environment "${KERF_MESA_LSAN}")
  if(ARG_WINDOW OR "${ARG_ARGS}" MATCHES "--backend;egl")
    set(environment "${KERF_UNLOADED_DRIVER_LSAN}")  # Mesa unloads these drivers (tests/CMakeLists.txt)
  endif()
  set_tests_properties(${prefix}.${ARG_NAME} PROPERTIES LABELS snapshot ENVIRONMENT "${environment}")
  if(ARG_WINDOW)  # xvfb-run -a races with another xvfb-run starting at the same moment
    set_tests_properties(${prefix}.${ARG_NAME} PROPERTIES RESOURCE_LOCK xvfb)
  endif()
endfunction()
