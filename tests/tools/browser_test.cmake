# Kerf's HTML pages in headless Chromium (tests/browser/pages.mjs), validated by html-validate, and
# their screenshots compared with tests/snapshots/browser_*.png by SSIM error as the pictures are
# (KERF_UPDATE_SNAPSHOTS=1 accepts new ones).
#   cmake -DCASE=report|part|hostile|realworld -DKERF=... -DCOMPARE=... -DSOURCE=... -DWORK=...
#         -DNODE=... -DTOOLS=... -DCHROMIUM=... -DTHRESHOLD=... [-DREALWORLD=...] -P browser_test.cmake
#   report     samples/ as a report: every page loads clean; the index and two pages' screenshots
#   realworld  samples/ and every real program: every page loads clean, the HTML is valid
#   part       kerf export samples/sector_r40.nc -o sector.html: clicks, keys, offline; a screenshot;
#              pages that open coloured by deviation, pass and slope
#   hostile    programs whose text and name try to be markup: their report pages and 3D page
if(NOT THRESHOLD)
  message(FATAL_ERROR "no SSIM threshold given (-DTHRESHOLD): a comparison against 0 is not one")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/shots")
set(ENV{KERF_TEST_TOOLS} "${TOOLS}")
set(ENV{CHROMIUM} "${CHROMIUM}")
unset(ENV{DISPLAY})

# From the source folder: the pages name the programs as given (samples/...), the same on every clone.
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${SOURCE}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# The pages in the browser: pages.mjs says what failed.
function(browse)
  run("${NODE}" "${SOURCE}/tests/browser/pages.mjs" ${ARGN})
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "in ${CHROMIUM}: ${err}${out}")
  endif()
endfunction()

function(validate)
  run("${TOOLS}/node_modules/.bin/html-validate" ${ARGN})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "html-validate: ${out}${err}")
  endif()
endfunction()

include(${CMAKE_CURRENT_LIST_DIR}/compare_snapshot.cmake)
function(compare_shot name)
  set(shot "${WORK}/shots/${name}.png")
  if(NOT EXISTS "${shot}")
    message(FATAL_ERROR "no screenshot ${shot}")
  endif()
  kerf_compare_snapshot("${COMPARE}" "${SOURCE}/tests/snapshots/browser_${name}.png" "${shot}" "${THRESHOLD}"
                        "${WORK}/shots/${name}.diff.png")
endfunction()

if(CASE STREQUAL "report")
  run("${KERF}" check samples --format html -o "${WORK}/report")
  if(NOT EXISTS "${WORK}/report/index.html")
    message(FATAL_ERROR "no report (exit ${rc}): ${err}")
  endif()
  browse(report "${WORK}/report" "${WORK}/shots" taper_punch_2deg.nc.html wire_crossing.nc.html)
  foreach(name IN ITEMS index taper_punch_2deg.nc wire_crossing.nc)
    compare_shot(${name})
  endforeach()
elseif(CASE STREQUAL "realworld")
  run("${KERF}" check "${SOURCE}/samples" "${REALWORLD}" --format html -o "${WORK}/report")
  file(GLOB pages "${WORK}/report/*.html")
  list(LENGTH pages n)
  if(n LESS 100)
    message(FATAL_ERROR "the report of samples/ and ${REALWORLD} has ${n} pages (exit ${rc}): ${err}")
  endif()
  browse(report "${WORK}/report" "${WORK}/shots")
  validate(${pages})
elseif(CASE STREQUAL "part")
  run("${KERF}" export samples/sector_r40.nc -o "${WORK}/sector.html")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "kerf export -o sector.html: exit ${rc}: ${err}")
  endif()
  validate("${WORK}/sector.html")
  browse(part "${WORK}/sector.html" "${WORK}/shots")
  compare_shot(sector_r40_line15)
  # Each colouring a page opens in: against a drawing, by pass, by slope.
  run("${KERF}" export samples/plate.nc --drawing samples/plate.dxf -o "${WORK}/plate.html")
  browse(open deviation "${WORK}/plate.html")
  run("${KERF}" export tests/passes/die_robofil_circle.nc -o "${WORK}/die.html")
  browse(open pass "${WORK}/die.html")
  run("${KERF}" export samples/taper_punch_2deg.nc -o "${WORK}/taper.html")
  browse(open slope "${WORK}/taper.html")
elseif(CASE STREQUAL "hostile")
  file(GLOB hostile "${SOURCE}/tests/bad/html_*.nc")  # in the bad-input corpus, each with its diagnostic
  file(MAKE_DIRECTORY "${WORK}/in")
  # A file name that tries to be markup too (not kept in the repository: '<' is no file name there).
  file(COPY_FILE "${SOURCE}/tests/bad/html_script_comment.nc" "${WORK}/in/a<b>x.nc")
  run("${KERF}" check ${hostile} "${WORK}/in" --format html -o "${WORK}/report")
  file(GLOB pages "${WORK}/report/*.html")
  list(FILTER pages EXCLUDE REGEX "/index\\.html$")
  run("${KERF}" export "${WORK}/in/a<b>x.nc" -o "${WORK}/a_b_x.html")
  validate(${pages} "${WORK}/a_b_x.html")
  browse(hostile ${pages} "${WORK}/a_b_x.html")
else()
  message(FATAL_ERROR "unknown CASE ${CASE}")
endif()
