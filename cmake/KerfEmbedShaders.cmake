# Shader sources compiled into a library as strings: shaders/surface.vert becomes
# kerf::render::shaders::kSurfaceVert. Regenerated when a shader changes.
#   kerf_embed_shaders(OUTPUT <file.cpp> SOURCES <shader files...>)
# Script mode (the build step): cmake -DOUTPUT=... -DSOURCES=a;b -P KerfEmbedShaders.cmake
function(kerf_shader_symbol file out)
  get_filename_component(name "${file}" NAME)
  string(REPLACE "." "_" name "${name}")
  string(REGEX MATCHALL "[a-z0-9]+" parts "${name}")
  set(symbol "k")
  foreach(p IN LISTS parts)
    string(SUBSTRING "${p}" 0 1 first)
    string(SUBSTRING "${p}" 1 -1 rest)
    string(TOUPPER "${first}" first)
    string(APPEND symbol "${first}${rest}")
  endforeach()
  set(${out} "${symbol}" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
  set(text "// Generated from shaders/ by cmake/KerfEmbedShaders.cmake: do not edit.\n")
  string(APPEND text "namespace kerf::render::shaders {\n")
  foreach(file IN LISTS SOURCES)
    kerf_shader_symbol("${file}" symbol)
    file(READ "${file}" source)
    string(APPEND text "extern const char* const ${symbol};\nconst char* const ${symbol} = R\"kerf_glsl(${source})kerf_glsl\";\n")
  endforeach()
  string(APPEND text "}  // namespace kerf::render::shaders\n")
  file(WRITE "${OUTPUT}.tmp" "${text}")
  file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
  return()
endif()

set(KERF_EMBED_SHADERS_SCRIPT "${CMAKE_CURRENT_LIST_FILE}")
function(kerf_embed_shaders)
  cmake_parse_arguments(ARG "" "OUTPUT" "SOURCES" ${ARGN})
  add_custom_command(OUTPUT "${ARG_OUTPUT}"
                     COMMAND ${CMAKE_COMMAND} "-DOUTPUT=${ARG_OUTPUT}" "-DSOURCES=${ARG_SOURCES}" -P
                             "${KERF_EMBED_SHADERS_SCRIPT}"
                     DEPENDS ${ARG_SOURCES} "${KERF_EMBED_SHADERS_SCRIPT}"
                     COMMENT "Embedding shaders" VERBATIM)
endfunction()
