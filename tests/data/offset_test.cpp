// The wire offset against GEOS (tests/tools/offset_oracle.py, Debian's python3-shapely: buffer with
// round joins as an independent oracle), through the kerf program (`kerf check --json --offset R
// --side S`): every closed contour of every real drawing in ../shared/realworld/dxf, random closed
// polylines with arcs, a die with a slot narrower than the wire and a contour whose inside offset
// splits in two, at R = 0.15 and 1.0 mm on both sides. Each wire path must enclose GEOS's area within
// 0.01 % (or the oracle's own flattening slack, for tiny areas), lie within 2 um of GEOS's boundary
// (discrete Hausdorff distance) and have as many loops as GEOS has parts.
#include "data_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

class OffsetAgainstGeos : public testing::Test {
 public:
  OffsetAgainstGeos(std::string drawing, std::string name) : drawing_(std::move(drawing)), name_(std::move(name)) {}

  void TestBody() override {
    const fs::path work = fs::path(KERF_OFFSET_WORK);
    fs::create_directories(work);
    const fs::path out = work / (name_ + ".json");
    const std::string command = "'" + std::string(KERF_PYTHON) + "' '" + std::string(KERF_OFFSET_ORACLE) + "' '" +
                                std::string(KERF_PROGRAM) + "' '" + drawing_ + "' '" + work.string() +
                                "' 0.15 1.0 > '" + out.string() + "'";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "the GEOS oracle failed on " << drawing_ << " (python3-shapely, python3-ezdxf: .ci/install-deps.sh --tests)";
    const json report = json::parse(kerf::test::readFile(out));
    double worstArea = 0.0, worstDistance = 0.0;
    std::size_t compared = 0, degenerate = 0;
    for (const json& c : report["cases"]) {
      const std::string what = c["file"].get<std::string>() + " contour " + std::to_string(c["contour"].get<int>());
      if (c.contains("degenerate")) {
        ++degenerate;
        continue;
      }
      const std::string where = what + " " + c["side"].get<std::string>() + " R " + c["radius"].dump();
      ++compared;
      const double kerfArea = c["kerf_area"].get<double>(), geosArea = c["geos_area"].get<double>();
      const double allowed = std::max(1e-4 * geosArea, c["area_slack"].get<double>());
      EXPECT_LE(std::abs(kerfArea - geosArea), allowed) << where;
      EXPECT_EQ(c["loops"].get<int>(), c["geos_parts"].get<int>()) << where;
      if (c["loops"].get<int>() > 0) {
        EXPECT_LE(c["hausdorff"].get<double>(), 0.002) << where;
        worstDistance = std::max(worstDistance, c["hausdorff"].get<double>());
      }
      if (geosArea > 0) worstArea = std::max(worstArea, std::abs(kerfArea - geosArea) / geosArea);
      if (name_ == "slot" && c["side"] == "inside" && c["radius"].get<double>() == 0.15) {
        EXPECT_GE(c["lost"].get<int>(), 1) << "the slot narrower than the wire is named";
      }
      if (name_ == "split" && c["side"] == "inside" && c["radius"].get<double>() == 0.15) {
        EXPECT_EQ(c["loops"].get<int>(), 2) << "the pinched contour's inside offset splits in two";
      }
    }
    std::printf(
        "%s: %zu wire paths compared with GEOS (%zu contours of no area left out): area within %.3g, "
        "Hausdorff <= %.4f mm\n",
        name_.c_str(), compared, degenerate, worstArea, worstDistance);
  }

 private:
  std::string drawing_, name_;
};

void add(const std::string& drawing, std::string name) {
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  testing::RegisterTest("offset_geos_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                        [drawing, name]() -> testing::Test* { return new OffsetAgainstGeos(drawing, name); });
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const fs::path dir = fs::path(KERF_REALWORLD_DIR) / "dxf";
  if (fs::is_directory(dir))  // the corpus lives beside the project
    for (const fs::path& f : kerf::test::sortedEntries(dir, false, ".dxf")) add(f.string(), f.stem().string());
  add("random:1:20", "random_1");
  add("random:2:20", "random_2");
  add("random:3:20", "random_3");
  add("shape:slot", "slot");
  add("shape:split", "split");
  return RUN_ALL_TESTS();
}
