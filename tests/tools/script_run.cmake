# What the CMake script tests share (cli_test.cmake, install_test.cmake): run() a command, expect().
# Each run goes through lsan_retry.sh: in the ASan build, LeakSanitizer's tracer sometimes crashes at
# exit, which is the sanitizer's fault and not the case's (the script's head says which failure).
# run(COMMAND ARGS...): sets rc, out and err in the caller.
function(run)
  execute_process(COMMAND sh ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/lsan_retry.sh ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()
# expect("message" <if() condition words...>): fails the test with the last run's output. Empty
# arguments vanish from ARGN: compare lengths, not "" strings.
function(expect msg)
  if(NOT (${ARGN}))
    message(FATAL_ERROR "${CASE}: ${msg}\nexit ${rc}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
endfunction()
