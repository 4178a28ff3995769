# KERF_SANITIZER: none | address | undefined | address,undefined
# Applied to every target in the tree so libraries and tests agree on the runtime.
if(NOT KERF_SANITIZER STREQUAL "none" AND NOT KERF_SANITIZER STREQUAL "")
  string(REPLACE ";" "," _kerf_san "${KERF_SANITIZER}")
  string(REPLACE "," ";" _kerf_san_list "${_kerf_san}")
  foreach(_s IN LISTS _kerf_san_list)
    if(NOT _s MATCHES "^(address|undefined)$")
      message(FATAL_ERROR "KERF_SANITIZER: unknown sanitizer '${_s}' (use address, undefined or address,undefined)")
    endif()
  endforeach()
  add_compile_options(-fsanitize=${_kerf_san} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${_kerf_san})
  message(STATUS "Kerf: sanitizers ${_kerf_san}")
endif()
