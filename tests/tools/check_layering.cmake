# The dependency direction of the design (README: layout), checked on the sources:
#  - geometry includes only its own headers, Eigen and the standard library;
#  - converter includes no viewer, window or GL header;
#  - libraries never touch the process: no printing to the terminal, no exit(), no opening files,
#    no environment, no signal handlers, no memory mappings (the program reads the environment
#    once and passes the values in).
#   cmake -DSOURCE=<repo> -P check_layering.cmake
set(problems "")
file(GLOB_RECURSE geometry_files "${SOURCE}/geometry/*.h" "${SOURCE}/geometry/*.cpp")
file(GLOB_RECURSE converter_files "${SOURCE}/converter/*.h" "${SOURCE}/converter/*.cpp")
foreach(f IN LISTS geometry_files)
  file(STRINGS "${f}" includes REGEX "^#include")
  foreach(inc IN LISTS includes)
    if(NOT inc MATCHES "^#include (\"kerf/geometry/|\"[a-z_]+\\.h\"|<Eigen/|<unsupported/Eigen/|<[a-z_]+>)")
      string(APPEND problems "${f}: geometry may include only Eigen and itself: ${inc}\n")
    endif()
  endforeach()
endforeach()
# forbid_includes(<files> <regex> <who>): an #include of the files that matches regex is a problem.
function(forbid_includes files regex who)
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^#include")
    foreach(inc IN LISTS includes)
      if(inc MATCHES "${regex}")
        string(APPEND problems "${f}: ${who} may not include ${inc}\n")
      endif()
    endforeach()
  endforeach()
  set(problems "${problems}" PARENT_SCOPE)
endfunction()
forbid_includes("${converter_files}" "kerf/(viewer|render|headless|export)|GL|glfw|imgui|vtk" "converter")
# Inside converter, folders by role, each including only itself and the roles before it:
#   nc (source text, numbers, diagnostics, parser) < interpret < structure < check < formats < cam < report;
# the two headers at the top, toolpath.h (data every role shares) and pipeline.h (the one route
# of the commands), and pipeline.cpp beside them. No other source sits at the top of src/.
set(converter_roles nc interpret structure check formats cam report)
list(LENGTH converter_roles role_count)
math(EXPR last_role "${role_count} - 1")
foreach(i RANGE ${last_role})
  list(GET converter_roles ${i} role)
  set(later "")
  foreach(j RANGE ${last_role})
    if(j GREATER i)
      list(GET converter_roles ${j} other)
      list(APPEND later "${other}")
    endif()
  endforeach()
  file(GLOB_RECURSE role_files "${SOURCE}/converter/src/${role}/*" "${SOURCE}/converter/include/kerf/converter/${role}/*")
  if(later)
    list(JOIN later "|" later_alternatives)
    forbid_includes("${role_files}" "kerf/converter/(${later_alternatives})/|kerf/converter/pipeline\\.h" "converter/${role}")
  else()
    forbid_includes("${role_files}" "kerf/converter/pipeline\\.h" "converter/${role}")
  endif()
endforeach()
# The sources of the top-level headers stand at the top: pipeline.h, convert.h (convert and cam on
# the pipeline's result, as the commands run them) and toolpath.h, which every role shares; every
# other source in its role's folder.
file(GLOB top_sources "${SOURCE}/converter/src/*")
foreach(f IN LISTS top_sources)
  if(NOT IS_DIRECTORY "${f}" AND NOT f MATCHES "/(pipeline|convert|toolpath)\\.cpp$")
    string(APPEND problems "${f}: a converter source belongs in its role's folder (${converter_roles})\n")
  endif()
endforeach()
# A public header and its source share a name: include/kerf/converter/<role>/<name>.h is made by
# src/<role>/<name>.cpp. Header-only: toolpath.h (data) and nc/diagnostic_table.h (the table).
file(GLOB_RECURSE public_headers RELATIVE "${SOURCE}/converter/include/kerf/converter"
     "${SOURCE}/converter/include/kerf/converter/*.h")
foreach(h IN LISTS public_headers)
  string(REGEX REPLACE "\\.h$" ".cpp" cpp "${h}")
  if(NOT EXISTS "${SOURCE}/converter/src/${cpp}" AND NOT h MATCHES "^(toolpath|nc/diagnostic_table)\\.h$")
    string(APPEND problems "converter/include/kerf/converter/${h}: no source of the same name (converter/src/${cpp})\n")
  endif()
endforeach()
# The renderer and the headless contexts know nothing of windows or ImGui (README: layout).
file(GLOB_RECURSE render_files "${SOURCE}/viewer/include/kerf/*.h" "${SOURCE}/viewer/src/render/*"
     "${SOURCE}/viewer/src/headless/*" "${SOURCE}/viewer/src/export/*" "${SOURCE}/shaders/*")
forbid_includes("${render_files}" "glfw|GLFW|imgui" "the renderer")
# The program's own sources (viewer/src/cli) load no graphics library: the commands that draw are
# in the drawing module (viewer/src/draw, loaded by cli/draw_module.cpp).
file(GLOB cli_files "${SOURCE}/viewer/src/cli/*")
forbid_includes("${cli_files}" "kerf/(render|headless|export)/|window/|ui/|draw\\.h|GL|glfw|imgui|vtk"
                "the program (not its drawing module)")
foreach(f IN LISTS geometry_files converter_files)
  file(STRINGS "${f}" lines
       REGEX "std::cout|std::cerr|std::exit|[^_a-z]exit\\(|abort\\(|fopen|ifstream|ofstream|[^n]printf\\(|getenv|sigaction|signal\\(|mmap|madvise")
  foreach(l IN LISTS lines)
    string(APPEND problems "${f}: a library must not touch the process: ${l}\n")
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
