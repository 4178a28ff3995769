# Runs `kerf check FILE` and requires exit code 1 and the diagnostic written on FILE's first
# line (after "; "; a DXF file: its second line, in a 999 comment) in its standard error, prefixed with the file name.
#   cmake -DKERF=... -DFILE=... -DWORKDIR=... -P expect_diagnostic.cmake
# A DXF file states it in a `999` comment instead: its second line. A curve file, after "# ".
file(READ "${FILE}" head LIMIT 1000)
if(FILE MATCHES "\\.dxf$")
  string(FIND "${head}" "\n" eol)
  math(EXPR from "${eol} + 1")
  string(SUBSTRING "${head}" ${from} -1 head)
  string(PREPEND head "; ")
endif()
string(FIND "${head}" "\n" eol)
math(EXPR len "${eol} - 2")
string(SUBSTRING "${head}" 2 ${len} expected)  # after "; "
get_filename_component(name "${FILE}" NAME)
execute_process(COMMAND "${KERF}" check "${name}" WORKING_DIRECTORY "${WORKDIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "kerf check ${name}: exit code ${rc}, expected 1\n${err}")
endif()
string(FIND "${err}" "${name}:${expected}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "kerf check ${name}: expected\n  ${name}:${expected}\nin\n${err}")
endif()
if(err MATCHES "runtime error|AddressSanitizer|LeakSanitizer")
  message(FATAL_ERROR "sanitizer report:\n${err}")
endif()
