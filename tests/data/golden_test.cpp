// tests/golden/<case>/: input.nc, an optional `options` file (key = value lines), and the
// expected outputs: expected.trace (Toolpath + diagnostics) and expected.bp95d (the point file,
// or the diagnostics when it cannot be written). Byte compare; a capped diff on failure.
// KERF_UPDATE_GOLDEN=1 rewrites the expectations instead of comparing.
#include "kerf/converter/analysis.h"
#include "kerf/converter/checks.h"
#include "kerf/converter/dialect.h"
#include "kerf/converter/points.h"
#include "kerf/converter/report.h"

#include "data_test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

namespace {

using namespace kerf::converter;
namespace fs = std::filesystem;

std::map<std::string, std::string> readOptions(const fs::path& file) {
  std::map<std::string, std::string> out;
  if (!fs::exists(file)) return out;
  for (const std::string& line : kerf::test::splitLines(kerf::test::readFile(file))) {
    const auto eq = line.find('=');
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(" \t"));
      s.erase(s.find_last_not_of(" \t\r") + 1);
      return s;
    };
    out[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  return out;
}

class GoldenTest : public testing::Test {
 public:
  explicit GoldenTest(fs::path dir) : dir_(std::move(dir)) {}

  void TestBody() override {
    const auto opt = readOptions(dir_ / "options");
    InterpreterOptions io;
    if (opt.count("integer_unit") && opt.at("integer_unit") == "um") io.integerUnit = IntegerUnit::Micrometre;
    if (opt.count("arc_centre")) {
      const std::string& m = opt.at("arc_centre");
      io.arcCentre = m == "reversed"   ? ArcCentreMode::Reversed
                     : m == "absolute" ? ArcCentreMode::Absolute
                                       : ArcCentreMode::Incremental;
    }
    if (opt.count("dialect")) io.dialect = parseDialect(opt.at("dialect"));
    if (opt.count("thickness")) io.thickness = std::stod(opt.at("thickness"));
    if (opt.count("upper_z")) io.upperZ = std::stod(opt.at("upper_z"));
    if (opt.count("program_z")) io.programZ = std::stod(opt.at("program_z"));
    PointRequest req;
    if (opt.count("step")) req.sampling = kerf::geometry::Sampling::step(std::stod(opt.at("step")));
    if (opt.count("tolerance")) req.sampling = kerf::geometry::Sampling::tolerance(std::stod(opt.at("tolerance")));
    if (opt.count("max_points")) req.maxPoints = std::stoul(opt.at("max_points"));
    if (opt.count("start_line")) req.startLine = static_cast<std::uint32_t>(std::stoul(opt.at("start_line")));

    SourceFile src("input.nc", kerf::test::readFile(dir_ / "input.nc"));
    Diagnostics diags(200);
    const Analysis a = analyse(src, io, diags);
    checkToolpath(a.toolpath, &src, {}, diags);
    diags.sortByPosition();
    compare("expected.trace", formatTrace(a.toolpath, diags));

    PointProfile profile = bp95dProfile();
    std::optional<SourceFile> profileSource;
    Diagnostics emitDiags(50);
    if (opt.count("profile")) {
      profileSource.emplace(opt.at("profile"), kerf::test::readFile(dir_ / opt.at("profile")));
      auto parsed = parseProfile(*profileSource, emitDiags);
      ASSERT_TRUE(parsed.has_value()) << "profile does not parse";
      profile = *parsed;
    }
    std::string points;
    std::optional<Toolpath> flat;
    if (!diags.hasErrors()) {
      // A taper program is written at its `plane` (default lower), and both planes as points4.
      const auto plane = parsePlane(opt.count("plane") ? opt.at("plane") : "lower");
      ASSERT_TRUE(plane.has_value()) << "bad plane option";
      flat = toolpathAtPlane(a.toolpath, *plane, 0.001, &src, emitDiags);
    }
    if (flat) {
      const auto out = emitPoints(*flat, &src, profile, req, emitDiags);
      if (out) {
        points = "# " + std::to_string(out->points) + " points, " +
                 (out->sampling.mode == kerf::geometry::SamplingMode::Step ? "step " : "tolerance ") +
                 formatFixed(out->sampling.value, 9) + (out->fitted ? " (fitted)" : "") + ", max deviation " +
                 formatFixed(out->stats.maxDeviation, 9) + "\n" + out->text;
      }
      for (const auto& d : emitDiags.all()) points += "# " + formatDiagnostic(d);
    } else {
      points = "# not written: the program has errors\n";
    }
    compare("expected.bp95d", points);
    if (a.toolpath.isTaper()) {
      std::string both;
      Diagnostics d4(50);
      if (!diags.hasErrors()) {
        const auto out = emitPoints4(a.toolpath, &src, profile, req, false, d4);
        if (out) both = "# " + std::to_string(out->points) + " point pairs\n" + out->text;
        for (const auto& d : d4.all()) both += "# " + formatDiagnostic(d);
      } else {
        both = "# not written: the program has errors\n";
      }
      compare("expected.points4", both);
    }
  }

 private:
  void compare(const std::string& name, const std::string& actual) {
    const fs::path file = dir_ / name;
    if (const char* u = std::getenv("KERF_UPDATE_GOLDEN"); u && std::string(u) == "1") {
      kerf::test::writeFile(file, actual);
      return;
    }
    ASSERT_TRUE(fs::exists(file)) << file << " is missing; run with KERF_UPDATE_GOLDEN=1 to create it";
    const std::string expected = kerf::test::readFile(file);
    EXPECT_TRUE(expected == actual) << name << " differs:\n"
                                    << kerf::test::cappedDiff(expected, actual)
                                    << "(KERF_UPDATE_GOLDEN=1 accepts the new output)";
  }

  fs::path dir_;
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  for (const auto& dir : kerf::test::sortedEntries(KERF_GOLDEN_DIR, true)) {
    testing::RegisterTest("golden", dir.filename().string().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [dir]() -> testing::Test* { return new GoldenTest(dir); });
  }
  return RUN_ALL_TESTS();
}
