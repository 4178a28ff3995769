# kerf installed as a user installs it, and packaged as Debian installs it.
#   cmake -DBUILD=<build dir> -DSOURCE=<repo> -DWORK=<scratch> -DDEB=ON|OFF -P install_test.cmake
# 1. cmake --install into a temporary prefix: the installed kerf checks a sample, draws it (the
#    drawing module is found where it was installed), and the manual page, docs, samples and
#    machine profiles are there.
# 2. DEB: cpack -G DEB; dpkg-deb -c lists the program and the module, the package depends on
#    runtime libraries only (no -dev package), and the program unpacked from it checks a sample.
set(CASE install)
include(${CMAKE_CURRENT_LIST_DIR}/script_run.cmake)  # run(), expect(): kerf through lsan_retry.sh
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

set(prefix "${WORK}/prefix")
run(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${prefix}")
expect("cmake --install should succeed" rc EQUAL 0)
run("${prefix}/bin/kerf" check "${SOURCE}/samples/punch_outline.nc")
expect("the installed kerf should check the punch sample clean" rc EQUAL 0)
string(FIND "${out}" "verdict: ok" at)
expect("the installed kerf should print the verdict" NOT at EQUAL -1)
run("${prefix}/bin/kerf" render "${SOURCE}/samples/punch_outline.nc" -o "${WORK}/punch.png" --size 64x48)
expect("the installed kerf should find its drawing module and render" rc EQUAL 0 AND EXISTS "${WORK}/punch.png")
file(GLOB_RECURSE man "${prefix}/*/kerf.1")
file(GLOB_RECURSE codes "${prefix}/*/doc/kerf/diagnostics.md")
file(GLOB_RECURSE sample "${prefix}/*/doc/kerf/samples/punch_outline.nc")
file(GLOB_RECURSE profile "${prefix}/*/kerf/machines/sodick.profile")
expect("the manual page, docs, samples and profiles should be installed: '${man}' '${codes}' '${sample}' '${profile}'"
       man AND codes AND sample AND profile)
file(READ "${man}" page)
string(FIND "${page}" ".SH KERF CHECK" at)
expect("the manual page should hold kerf check's help" NOT at EQUAL -1)
string(FIND "${page}" "--format" at)
expect("the manual page should list check's --format" NOT at EQUAL -1)

if(DEB)
  run(cpack -G DEB -B "${WORK}/deb" --config "${BUILD}/CPackConfig.cmake")
  expect("cpack -G DEB should succeed" rc EQUAL 0)
  file(GLOB deb "${WORK}/deb/kerf_*.deb")
  expect("a kerf_*.deb should be made" deb)
  run(dpkg-deb -c "${deb}")
  expect("dpkg-deb -c should list the package" rc EQUAL 0)
  foreach(path "./usr/bin/kerf" "/kerf/libkerf-draw.so" "./usr/share/man/man1/kerf.1" "./usr/share/doc/kerf/ci.md")
    string(FIND "${out}" "${path}" at)
    expect("the package should hold ${path}" NOT at EQUAL -1)
  endforeach()
  run(dpkg-deb -f "${deb}" Depends)
  expect("the package should depend on the runtime libraries (VTK, GLFW, OSMesa)" out MATCHES "libvtk" AND out MATCHES
         "libglfw3" AND out MATCHES "libosmesa6")
  expect("the package should depend on no -dev package" NOT out MATCHES "-dev")
  run(dpkg-deb -x "${deb}" "${WORK}/unpacked")
  run("${WORK}/unpacked/usr/bin/kerf" check "${SOURCE}/samples/punch_outline.nc")
  expect("the kerf unpacked from the package should check the punch sample" rc EQUAL 0)
  run("${WORK}/unpacked/usr/bin/kerf" render "${SOURCE}/samples/punch_outline.nc" -o "${WORK}/deb.png" --size 64x48)
  expect("the kerf unpacked from the package should render" rc EQUAL 0)
endif()
