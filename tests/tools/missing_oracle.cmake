# A test that fails because an independent oracle the suite needs is not installed (CI=true: a
# missing oracle must not turn into a silently skipped check).
#   cmake -DWHAT=... -DPACKAGE=... -P missing_oracle.cmake
message(FATAL_ERROR "${WHAT} is not installed (Debian package ${PACKAGE}; bash .ci/install-deps.sh --tests installs it): "
                    "the tests that compare against it cannot run")
