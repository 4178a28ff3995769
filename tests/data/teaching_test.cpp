// Teaching (docs/teaching.md), through the kerf program: `kerf render --explain-line N` draws a
// block's construction and prints its marks' labels; the figures are kerf explain's.
#include "data_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace fs = std::filesystem;
using kerf::test::runCommand;

namespace {

const fs::path kSamples = fs::path(KERF_SAMPLES_DIR);

/// `kerf render FILE --explain-line LINE ARGS`: what it printed and its exit status.
kerf::test::CommandRun explainPicture(const std::string& file, int line, const std::string& args = {}) {
  const fs::path out =
      fs::path(KERF_TEACHING_WORK) / (fs::path(file).stem().string() + "_" + std::to_string(line) + ".png");
  fs::create_directories(out.parent_path());
  return runCommand("'" + std::string(KERF_PROGRAM) + "' render '" + (kSamples / file).string() + "' --explain-line " +
                    std::to_string(line) + " " + args + " -o '" + out.string() + "' 2>/dev/null");
}

/// The number after `key` in `text` (the first one), or NaN.
double numberAfter(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + key.size()));
}

}  // namespace

// The largest chord deviation drawn is the one kerf explain gives, for the same block and step.
TEST(teaching_test, the_deviation_drawn_is_explains) {
  struct Case {
    const char* file;
    int line;
    const char* step;
  };
  for (const Case& c :
       {Case{"sector_r40.nc", 15, "0.1"}, Case{"sector_r40.nc", 15, "1"}, Case{"sector_r40.nc", 15, "5"},
        Case{"punch_outline.nc", 14, "0.5"}, Case{"taper_punch_2deg.nc", 16, "0.2"}}) {
    SCOPED_TRACE(std::string(c.file) + " line " + std::to_string(c.line) + " step " + c.step);
    const auto drawn = explainPicture(c.file, c.line, std::string("--step ") + c.step);
    ASSERT_LE(drawn.status, 1) << drawn.out;
    const double picture = numberAfter(drawn.out, "max deviation ");
    const auto explained = runCommand("'" + std::string(KERF_PROGRAM) + "' explain --json --step " + c.step + " '" +
                                      (kSamples / c.file).string() + "' 2>/dev/null");
    const nlohmann::json j = nlohmann::json::parse(explained.out);
    double words = std::nan("");
    for (const nlohmann::json& m : j["moves"])
      if (m["line"] == c.line) {
        words = m["max_deviation"].get<double>();
        break;
      }
    ASSERT_FALSE(std::isnan(words)) << "kerf explain has no move on the line";
    EXPECT_GT(picture, 0.0);
    EXPECT_NEAR(picture, words, 5e-7) << drawn.out;  // the picture prints six decimals
  }
}

// Line 15 of the seed's sector, G03 X0 Y40. R40.: both candidate centres, the one taken and why.
TEST(teaching_test, an_r_arc_shows_both_centres) {
  const auto r = explainPicture("sector_r40.nc", 15, "--view top");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("centre taken: R > 0, the arc of at most 180 deg (zn = -1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rejected: the centre of the longer arc"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("chord 56.569 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("alpha 0.000 (seed, cw)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("beta -90.000 (seed, cw)"), std::string::npos) << r.out;
}

// An I J arc, a taper move, a wire-offset move: each its own marks.
TEST(teaching_test, ij_taper_and_offset_moves) {
  const auto ij = explainPicture("punch_outline.nc", 14);
  EXPECT_NE(ij.out.find("centre = start + (I, J); I J = (10.000, 0.000)"), std::string::npos) << ij.out;
  const auto taper = explainPicture("taper_punch_2deg.nc", 14);
  EXPECT_NE(taper.out.find("wire at the start, slope 2.000 deg"), std::string::npos) << taper.out;
  EXPECT_NE(taper.out.find("upper"), std::string::npos) << taper.out;
  const auto offset = explainPicture("inch_g91_bare_g41.nc", 23, "--offset 0.1");
  EXPECT_NE(offset.out.find("offset 0.100 mm left of travel (G41)"), std::string::npos) << offset.out;
  EXPECT_NE(offset.out.find("as programmed"), std::string::npos) << offset.out;
}

// A block in a program cut in several passes says which pass it belongs to.
TEST(teaching_test, a_block_says_its_pass) {
  const fs::path die = fs::path(KERF_PASSES_DIR) / "die_tab_cut_off.nc";
  const fs::path out = fs::path(KERF_TEACHING_WORK) / "die_tab_cut_off_20.png";
  const auto r = runCommand("'" + std::string(KERF_PROGRAM) + "' render '" + die.string() + "' --explain-line 20 -o '" +
                            out.string() + "' 2>/dev/null");
  EXPECT_LE(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("pass 2 of contour 1: a skim"), std::string::npos) << r.out;
}

// kerf explain says what each word sets and the modes in force, as the picture's caption does.
TEST(teaching_test, explain_says_the_words_and_modes) {
  const std::string sector = (kSamples / "sector_r40.nc").string();
  const auto text = runCommand("'" + std::string(KERF_PROGRAM) + "' explain '" + sector + "' 2>/dev/null");
  EXPECT_NE(text.out.find("  R40.: the radius; positive: the arc of at most 180 degrees\n"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("modes from line 13:\n  absolute (G90)"), std::string::npos) << text.out;
  const auto json = runCommand("'" + std::string(KERF_PROGRAM) + "' explain --json '" + sector + "' 2>/dev/null");
  const nlohmann::json j = nlohmann::json::parse(json.out);
  bool found = false;
  for (const nlohmann::json& m : j["moves"])
    if (m["line"] == 15) {
      found = true;
      ASSERT_EQ(m["words"].size(), 4u) << m.dump(1);
      EXPECT_EQ(m["words"][3]["word"], "R40.");
      EXPECT_EQ(m["modes"][0], "absolute (G90): X Y are the end point in the program's coordinates");
    }
  EXPECT_TRUE(found);
}

// A line with no move is said, with the nearest lines that have one.
TEST(teaching_test, a_line_without_a_move_is_said) {
  const auto r = runCommand("'" + std::string(KERF_PROGRAM) + "' render '" + (kSamples / "sector_r40.nc").string() +
                            "' --explain-line 2 -o /dev/null 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--explain-line 2: no move is programmed on that line; the nearest moves are on line 13"),
            std::string::npos)
      << r.out;
}
