# A test that fails because an independent oracle or data the suite needs is not there (CI=true: a
# missing oracle must not turn into a silently skipped check).
#   cmake -DWHAT=... -DPACKAGE=... -P missing_oracle.cmake     (a Debian package installs it)
#   cmake -DWHAT=... -DHOW=... -P missing_oracle.cmake         (where it should come from)
if(NOT DEFINED HOW)
  set(HOW "Debian package ${PACKAGE}; bash .ci/install-deps.sh --tests installs it")
endif()
message(FATAL_ERROR "${WHAT} is not there (${HOW}): the tests that compare against it cannot run")
