# lsan_retry.sh retries only LeakSanitizer's tracer crash, passes on the last run's output, and gives
# up after three runs; a leak report or any other failure is passed on at once.
#   cmake -DWORK=<scratch dir> -P lsan_retry_test.cmake
set(retry ${CMAKE_CURRENT_LIST_DIR}/lsan_retry.sh)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# fake.sh COUNTER CRASHES KIND: run n prints "run n"; runs up to CRASHES fail as KIND says.
file(WRITE "${WORK}/fake.sh" [=[
n=$(cat "$1" 2>/dev/null || echo 0); n=$((n + 1)); echo "$n" > "$1"
echo "run $n"
if [ "$n" -le "$2" ]; then
  case "$3" in
    tracer) echo "Tracer caught signal 11: addr=0x3390 pc=0x7fc90bee80f0 sp=0x7fc8f45fbd10" >&2
            echo "==11564==LeakSanitizer has encountered a fatal error." >&2 ;;
    leak)   echo "==11564==ERROR: LeakSanitizer: detected memory leaks" >&2 ;;
  esac
  exit 86
fi
echo "clean $n" >&2
]=])
function(check name crashes kind want_rc want_out want_runs)
  file(REMOVE "${WORK}/${name}.n")
  execute_process(COMMAND sh ${retry} sh ${WORK}/fake.sh ${WORK}/${name}.n ${crashes} ${kind}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(READ "${WORK}/${name}.n" runs)
  string(STRIP "${runs}" runs)
  if(NOT rc EQUAL want_rc OR NOT out STREQUAL "${want_out}" OR NOT runs EQUAL want_runs)
    message(FATAL_ERROR "${name}: exit ${rc} (want ${want_rc}), ${runs} runs (want ${want_runs}), stdout [${out}] (want [${want_out}])\nstderr: ${err}")
  endif()
endfunction()
check(two_tracer_crashes 2 tracer 0 "run 3\n" 3)
check(tracer_crash_every_time 9 tracer 86 "run 3\n" 3)
check(leak_report 1 leak 86 "run 1\n" 1)
check(clean 0 none 0 "run 1\n" 1)
