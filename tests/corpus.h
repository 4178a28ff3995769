// The real-program corpus: the programs and drawings other people wrote for real machines, kept
// outside the project (tests/CMakeLists.txt says where, once: KERF_REALWORLD_DIR). A test that
// cannot hold its claim without it says KERF_NEEDS_CORPUS(): where the corpus is missing the test
// is skipped, naming the folder, except in CI's build (KERF_CORPUS_REQUIRED), where it fails.
#pragma once

#include <filesystem>

namespace kerf::test {

inline std::filesystem::path realworldDir() { return KERF_REALWORLD_DIR; }
inline bool haveRealworld() { return std::filesystem::is_directory(realworldDir() / "iso2d"); }

}  // namespace kerf::test

#define KERF_NEEDS_CORPUS()                                                                  \
  do {                                                                                       \
    if (!::kerf::test::haveRealworld()) {                                                    \
      if (KERF_CORPUS_REQUIRED)                                                              \
        FAIL() << "the real-program corpus is not at " << ::kerf::test::realworldDir()       \
               << ": under CI the real programs must be read";                               \
      else                                                                                   \
        GTEST_SKIP() << "the real-program corpus is not at " << ::kerf::test::realworldDir() \
                     << " (KERF_REALWORLD_DIR)";                                             \
    }                                                                                        \
  } while (false)
