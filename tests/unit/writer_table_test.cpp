// The writer table (formats/emit.h): every writer in it is found by its name and has golden files
// (tests/golden/*/expected.NAME, which golden_test compares), so a writer added to the table
// without them fails here.
#include "kerf/converter/formats/emit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
using kerf::converter::Emitter;
using kerf::converter::emitters;
using kerf::converter::findEmitter;

TEST(writer_table_test, every_writer_is_found_by_name_and_has_golden_files) {
  std::set<std::string> names;
  for (const Emitter& e : emitters()) {
    EXPECT_TRUE(names.insert(std::string(e.name)).second) << e.name << " twice";
    EXPECT_EQ(findEmitter(e.name), &e) << e.name;
    EXPECT_FALSE(e.summary.empty()) << e.name;
    std::size_t golden = 0;
    for (const auto& dir : fs::directory_iterator(KERF_SOURCE_DIR "/tests/golden"))
      golden += fs::exists(dir.path() / ("expected." + std::string(e.name)));
    EXPECT_GT(golden, 0U) << e.name << ": no tests/golden/*/expected." << e.name;
  }
  EXPECT_TRUE(names.count("dxf")) << "the DXF writer is in the table";
  EXPECT_EQ(findEmitter("no such format"), nullptr);
}

}  // namespace
