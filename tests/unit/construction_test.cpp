// A block's construction (converter/report/construction.h) for every move of every sample and real
// program: finite marks, the words of the block read, the modes said, and an arc's deviation the
// one kerf explain prints (geometry::sample at the same step).
#include "kerf/converter/report/construction.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/pipeline.h"

#include <gtest/gtest.h>

#include "../corpus.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace kerf::converter;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool finite(const kerf::geometry::Segment& s) {
  return s.start.allFinite() && s.end.allFinite() && s.centre.allFinite() && std::isfinite(s.radius()) &&
         std::isfinite(s.sweep);
}

/// Every move's construction in `file`; the number of moves.
std::size_t checkFile(const fs::path& file) {
  PipelineOptions options;
  options.centreWords = true;
  const Pipeline p = runPipeline({file.string(), readText(file)}, options);
  if (!p.read) return 0;
  const ParseOptions parse = parseOptionsFor(p.machine);
  const auto sampling = kerf::geometry::Sampling::step(0.1);
  for (std::size_t i = 0; i < p.toolpath.moves.size(); ++i) {
    SCOPED_TRACE(file.string() + " move " + std::to_string(i) + " line " + std::to_string(p.toolpath.moves[i].line));
    const Construction c = constructionOf(*p.source, p.toolpath, &p.structure, sampling, i, parse);
    EXPECT_EQ(c.line, p.toolpath.moves[i].line);
    EXPECT_FALSE(c.marks.empty());
    for (const ConstructionMark& m : c.marks) EXPECT_TRUE(finite(m.segment)) << m.label;
    EXPECT_FALSE(c.modes.empty());
    // A move with a block of its own reads its words (a corner the wire offset added has none).
    if (!c.block.empty() && p.toolpath.format == InputFormat::Iso) {
      EXPECT_FALSE(c.words.empty()) << c.block;
    }
    const Move& m = p.toolpath.moves[i];
    if (m.kind == MoveKind::Arc) {
      EXPECT_TRUE(c.maxDeviation.has_value());
      if (c.maxDeviation) {
        EXPECT_EQ(*c.maxDeviation, kerf::geometry::sample(m.lower, sampling, nullptr).maxDeviation);
      }
    }
  }
  return p.toolpath.moves.size();
}

}  // namespace

TEST(construction_test, every_move_of_every_sample_and_real_program) {
  const fs::path realworld = kerf::test::realworldDir();
  std::size_t files = 0, moves = 0;
  for (const fs::path& folder : {fs::path(KERF_SAMPLES_DIR), fs::path(KERF_SAMPLES_DIR) / "bad", realworld / "iso2d",
                                 realworld / "xyuv", realworld / "polar"}) {
    if (!fs::is_directory(folder)) continue;
    for (const auto& f : fs::directory_iterator(folder)) {
      if (!f.is_regular_file() || f.path().extension() == ".dxf" || f.path().extension() == ".md") continue;
      moves += checkFile(f.path());
      ++files;
    }
  }
  KERF_NEEDS_CORPUS();  // the samples were checked; the counts below are the corpus's
  EXPECT_GT(files, 20u);
  EXPECT_GT(moves, 1000u);
  std::printf("constructions of %zu moves in %zu files\n", moves, files);
}
