# Warnings for Kerf's own targets. KERF_WERROR turns them into errors (CI does).
# -ffp-contract=off keeps floating-point results identical across compilers and
# optimisation levels, so golden files compare byte for byte. -fno-math-errno: Kerf never reads
# errno after a math function, so a square root is the instruction alone, without the branch to
# the library call that would set errno for a negative argument (the results are the same).
function(kerf_target_defaults target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
    -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
    -Wnull-dereference -Wdouble-promotion -Wimplicit-fallthrough
    -ffp-contract=off -fno-math-errno)
  # GCC 12 reports a false -Wrestrict inside std::string's operator+ at -O2 (GCC PR 105329).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
     AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(KERF_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
