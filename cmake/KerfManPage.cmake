# kerf(1) made from the program's own --help, so the manual says what the program does.
#   cmake -DKERF=<kerf> -DOUTPUT=<kerf.1> -DVERSION=<x.y.z> -DDATADIR=<share/kerf> -DDOCDIR=<doc> -P KerfManPage.cmake
# The page: NAME, SYNOPSIS, DESCRIPTION (the top-level help), one section per command (its help,
# verbatim), EXIT STATUS, ENVIRONMENT, FILES and SEE ALSO.
function(kerf_help out)
  execute_process(COMMAND "${KERF}" ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "kerf ${ARGN} --help failed (${rc})")
  endif()
  # roff: a backslash is \e, and a line may not start with '.' or '\''.
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

kerf_help(top)
set(page ".TH KERF 1 \"\" \"kerf ${VERSION}\" \"User Commands\"
.SH NAME
kerf \\- verify, explain and convert wire-EDM NC programs
.SH SYNOPSIS
.B kerf
.I command
[\\fIoptions\\fR] \\fIfile\\fR|\\fIfolder\\fR...
.SH DESCRIPTION
.nf
${top}.fi
")
foreach(command check explain convert render export view machines cam)
  kerf_help(help ${command})
  string(TOUPPER "${command}" title)
  string(APPEND page ".SH KERF ${title}\n.nf\n${help}.fi\n")
endforeach()
string(APPEND page ".SH EXIT STATUS
.TP
.B 0
no errors (warnings and notes allowed)
.TP
.B 1
a program has errors (under \\-W options as given)
.TP
.B 2
a usage or file problem: a file cannot be read, an option is wrong
.PP
kerf check of several files exits with the worst of their statuses.
.SH ENVIRONMENT
.TP
.B KERF_THREADS
threads to use (default: the machine's cores, at most 16); 1 runs serially
.TP
.B NO_COLOR
set and not empty: no colour with \\-\\-color auto
.SH FILES
.TP
.I ${DATADIR}/machines
the built-in machine profiles, as files to copy for \\-\\-machine FILE
.TP
.I ${DOCDIR}
the documentation: diagnostic codes, formats, CI integration (ci.md)
.SH SEE ALSO
The diagnostic codes: ${DOCDIR}/diagnostics.md
")
file(WRITE "${OUTPUT}" "${page}")
