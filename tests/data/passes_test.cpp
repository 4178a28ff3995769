// The multi-pass corpus (tests/passes/*.nc) through the kerf program: each file states, in `;`
// comment lines, the exit status `kerf check` must give (`; expect exit: N`), lines its pass
// table must hold (`; expect: TEXT`, each a part of one printed line) and the findings it must
// get (`; expect diagnostic: LINE CODE`: a diagnostic with that code at that line), and the options
// to check it with (`; options: --offsets FILE`, files named from the corpus folder). The lengths in
// them were worked out by hand from the drawing and the offsets (docs/passes.md).
#include "data_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

/// `kerf check FILE OPTIONS` (output and diagnostics), run in the corpus folder (OPTIONS name files
/// there).
kerf::test::CommandRun checkProgram(const fs::path& file, const std::string& options) {
  return kerf::test::runCommand("cd '" + file.parent_path().string() + "' && '" + std::string(KERF_PROGRAM) +
                                "' check '" + file.string() + "' " + options + " 2>&1");
}

class PassTable : public testing::Test {
 public:
  explicit PassTable(fs::path file) : file_(std::move(file)) {}
  void TestBody() override {
    std::vector<std::string> expected;
    std::vector<std::pair<std::string, std::string>> diagnostics;  // (":LINE:", "[CODE]")
    int exitStatus = -1;
    std::string options;
    for (const std::string& line : kerf::test::splitLines(kerf::test::readFile(file_))) {
      if (line.starts_with("; expect exit: ")) exitStatus = std::stoi(line.substr(15));
      if (line.starts_with("; expect: ")) expected.push_back(line.substr(10));
      if (line.starts_with("; options: ")) options = line.substr(11);
      if (line.starts_with("; expect diagnostic: ")) {
        const std::string what = line.substr(21);  // "LINE CODE"
        const std::size_t space = what.find(' ');
        ASSERT_NE(space, std::string::npos) << line;
        diagnostics.emplace_back(":" + what.substr(0, space) + ":", "[" + what.substr(space + 1) + "]");
      }
    }
    ASSERT_GE(exitStatus, 0) << file_ << " states no '; expect exit: N'";
    ASSERT_FALSE(expected.empty()) << file_ << " states no '; expect:' line";
    const kerf::test::CommandRun r = checkProgram(file_, options);
    EXPECT_EQ(r.status, exitStatus) << r.out;
    for (const std::string& e : expected)
      EXPECT_NE(r.out.find(e), std::string::npos) << "missing: " << e << "\n" << r.out;
    const std::vector<std::string> printed = kerf::test::splitLines(r.out);
    for (const auto& [at, code] : diagnostics)
      EXPECT_TRUE(std::any_of(printed.begin(), printed.end(),
                              [&](const std::string& l) {
                                return l.find(file_.filename().string() + at) != std::string::npos &&
                                       l.find(code) != std::string::npos;
                              }))
          << "no " << code << " at line " << at << "\n"
          << r.out;
  }

 private:
  fs::path file_;
};

void registerCorpus() {
  const fs::path dir = KERF_PASSES_DIR;
  const std::vector<fs::path> files = kerf::test::sortedEntries(dir, false, ".nc");
  if (files.empty()) {
    testing::RegisterTest("passes_test", "corpus_is_missing", nullptr, nullptr, __FILE__, __LINE__,
                          [dir]() -> testing::Test* {
                            struct Missing : testing::Test {
                              fs::path d;
                              explicit Missing(fs::path p) : d(std::move(p)) {}
                              void TestBody() override { FAIL() << "no program in " << d; }
                            };
                            return new Missing(dir);
                          });
    return;
  }
  for (const fs::path& f : files)
    testing::RegisterTest("passes_test", f.stem().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [f]() -> testing::Test* { return new PassTable(f); });
}

}  // namespace

namespace {

/// What `kerf ARGS FILE` writes to standard output.
std::string kerfOutput(const std::string& args, const fs::path& file) {
  return kerf::test::runCommand("'" + std::string(KERF_PROGRAM) + "' " + args + " '" + file.string() + "' 2>/dev/null")
      .out;
}

/// The three-pass die's structure as JSON and SARIF carry it (docs/passes.md).
void expectDieStructure(const nlohmann::json& st) {
  ASSERT_EQ(st.at("contours").size(), 1u) << st.dump(2);
  const nlohmann::json& passes = st["contours"][0]["passes"];
  ASSERT_EQ(passes.size(), 3u) << st.dump(2);
  const char* registers[] = {"H001", "H002", "H003"};
  const double offsets[] = {0.18, 0.11, 0.085};
  const char* sides[] = {"G41", "G42", "G41"};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(passes[k]["register"], registers[k]);
    EXPECT_NEAR(passes[k]["offset_mm"].get<double>(), offsets[k], 1e-9);
    EXPECT_EQ(passes[k]["side"], sides[k]);
    EXPECT_EQ(passes[k]["kept"], "inside");  // a die opening, each pass inside it
    EXPECT_TRUE(passes[k]["closes"].get<bool>());
    EXPECT_FALSE(passes[k]["cut_off"].get<bool>());
  }
  EXPECT_NEAR(passes[0]["length_mm"].get<double>(), 98.2, 1e-9);  // docs/passes.md, worked example
  EXPECT_EQ(passes[1]["direction"], "clockwise");
}

TEST(passes_test, json_and_sarif_carry_the_structure) {
  const fs::path die = fs::path(KERF_PASSES_DIR) / "die_three_passes.nc";
  const nlohmann::json j = nlohmann::json::parse(kerfOutput("check --json", die));
  expectDieStructure(j.at("summary").at("structure"));
  const nlohmann::json sarif = nlohmann::json::parse(kerfOutput("check --format sarif", die));
  expectDieStructure(sarif.at("runs").at(0).at("artifacts").at(0).at("properties").at("structure"));
}

// docs/passes.md's worked example: the three-pass die at 20 mm, by hand from the program's
// coordinates. Each pass runs round a square of side 20 - 2 x offset and in and out along half
// of it: 4 s + s = 5 s mm. The rough cut at 100 mm²/min over 20 mm = 5 mm/min, the skims at
// 10 mm/min (the generic profile's model), one threading of 30 s, no rapid.
TEST(passes_test, the_time_estimate_is_the_hand_calculation) {
  const fs::path die = fs::path(KERF_PASSES_DIR) / "die_three_passes.nc";
  const double side[] = {20 - 2 * 0.18, 20 - 2 * 0.11, 20 - 2 * 0.085};
  const double minutes[] = {5 * side[0] / (100.0 / 20.0), 5 * side[1] / 10.0, 5 * side[2] / 10.0};
  const double total = minutes[0] + minutes[1] + minutes[2] + 30.0 / 60.0;  // 39.945
  const nlohmann::json st =
      nlohmann::json::parse(kerfOutput("check --json --thickness 20", die)).at("summary").at("structure");
  const nlohmann::json& passes = st.at("contours").at(0).at("passes");
  ASSERT_EQ(passes.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(passes[k]["minutes"].get<double>(), minutes[k], 1e-9) << k;
  EXPECT_NEAR(st["time"]["total_min"].get<double>(), total, 1e-9);
  EXPECT_NEAR(total, 39.945, 1e-9);
  EXPECT_TRUE(st["time"]["complete"].get<bool>());
  EXPECT_NE(kerfOutput("check --thickness 20", die).find("time 39.9 min (cutting 39.4, rapids 0.00, threading 0.50)"),
            std::string::npos);

  // --speed: every cut at that speed, whatever the thickness.
  const nlohmann::json fast =
      nlohmann::json::parse(kerfOutput("check --json --speed 4", die)).at("summary").at("structure");
  EXPECT_NEAR(fast["time"]["total_min"].get<double>(), 5 * (side[0] + side[1] + side[2]) / 4.0 + 0.5, 1e-9);

  // No thickness: the rough cut has no time, and the total says it is a lower bound.
  const nlohmann::json open = nlohmann::json::parse(kerfOutput("check --json", die)).at("summary").at("structure");
  EXPECT_TRUE(open["contours"][0]["passes"][0]["minutes"].is_null());
  EXPECT_FALSE(open["time"]["complete"].get<bool>());
  EXPECT_NEAR(open["time"]["total_min"].get<double>(), minutes[1] + minutes[2] + 0.5, 1e-9);
}

// kerf explain marks where each pass begins and ends and which moves lead in and out: the tab die's
// three passes, in text (each mark before the block it names) and in JSON.
TEST(passes_test, explain_marks_where_passes_begin_and_end) {
  const fs::path die = fs::path(KERF_PASSES_DIR) / "die_tab_cut_off.nc";
  const std::string text = kerfOutput("explain", die);
  const std::size_t begin2 = text.find("== pass 2 of contour 1 begins");
  const std::size_t end1 = text.find("== pass 1 of contour 1 ends: it leaves a tab of 2.000 mm");
  const std::size_t line18 = text.find("\nline 18: G42 H002");
  ASSERT_NE(begin2, std::string::npos) << text;
  ASSERT_NE(end1, std::string::npos) << text;
  EXPECT_LT(end1, begin2);
  EXPECT_LT(begin2, line18);
  EXPECT_NE(text.find("the cut-off through the tab"), std::string::npos);
  EXPECT_NE(text.find("lead-in of pass 3 of contour 1"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(kerfOutput("explain --json", die));
  std::size_t leadIns = 0, along = 0;
  for (const nlohmann::json& m : j.at("moves")) {
    ASSERT_TRUE(m.contains("pass")) << m.dump();
    leadIns += m["pass"]["role"] == "lead-in";
    along += m["pass"]["role"] == "contour";
    if (m["line"] == 18) {
      EXPECT_EQ(m["pass"]["pass"], 2);
    }
  }
  EXPECT_EQ(leadIns, 3u);
  EXPECT_GT(along, 9u);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  registerCorpus();
  return RUN_ALL_TESTS();
}
