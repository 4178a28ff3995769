// Every DXF drawing in ../shared/realworld/dxf read by Kerf (`kerf check FILE --json`) and by
// ezdxf (tests/tools/dxf_oracle.py, Debian's python3-ezdxf and python3-shapely: an independent
// reader): the model-space entity counts by type must be equal, the total length of the contour
// geometry (INSERTs expanded, bulges, splines and ellipses) equal within what ezdxf's flattening of
// curves can lose (it states the bound), and where no node joins
// more than two ends, the chaining must agree too — as many contours, as many closed, and the
// closed ones enclosing the same areas.
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

std::string run(const std::string& command, const fs::path& out, int& exit) {
  const int status = std::system((command + " > '" + out.string() + "'").c_str());
  exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return kerf::test::readFile(out);
}

// Issue 41: kerf cam that refuses to write (its program crosses itself when read back) names the
// program it made, not the output file it did not write.
TEST(cam_test, a_refused_program_is_named_as_not_written) {
  const fs::path drawing = fs::path(KERF_REALWORLD_DIR) / "dxf" / "cnc3-12345.dxf";
  ASSERT_TRUE(fs::exists(drawing)) << "the real corpus is missing: " << drawing;
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  const fs::path out = work / "refused.nc";
  fs::remove(out);
  int exit = 0;
  const std::string err = run("('" + std::string(KERF_PROGRAM) + "' cam '" + drawing.string() + "' --offset 0.1 -o '" +
                                  out.string() + "' 2>&1)",
                              work / "refused.log", exit);
  EXPECT_EQ(exit, 1) << err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(err.find("<not written: " + out.string() + ">:16:1: error:"), std::string::npos) << err;
  EXPECT_EQ(err.find(out.string() + ":"), std::string::npos) << "a line of a file that is not there: " << err;
}

class DxfAgainstEzdxf : public testing::Test {
 public:
  explicit DxfAgainstEzdxf(fs::path file) : file_(std::move(file)) {}

  void TestBody() override {
    const fs::path work = fs::path(KERF_DXF_WORK);
    fs::create_directories(work);
    const std::string name = file_.filename().string();
    int exit = 0;
    const std::string oracleText =
        run("'" + std::string(KERF_PYTHON) + "' '" + std::string(KERF_DXF_ORACLE) + "' '" + file_.string() + "' 0.001",
            work / (name + ".ezdxf.json"), exit);
    ASSERT_EQ(exit, 0) << "the ezdxf oracle failed on " << file_ << " (python3-ezdxf, python3-shapely: "
                       << ".ci/install-deps.sh --tests)";
    const std::string kerfText =
        run("'" + std::string(KERF_PROGRAM) + "' check --json '" + file_.string() + "' 2>/dev/null",
            work / (name + ".kerf.json"), exit);
    ASSERT_LT(exit, 2) << file_;
    const json oracle = json::parse(oracleText);
    const json report = json::parse(kerfText);
    ASSERT_TRUE(report.contains("drawing")) << kerfText.substr(0, 500);
    const json& d = report["drawing"];
    EXPECT_EQ(report["summary"]["format"], "dxf");

    // Entity counts by type.
    EXPECT_EQ(d["entities"], oracle["entities"]) << file_;

    // Length of everything that can be a contour.
    double length = 0.0;
    std::vector<double> areas;
    std::size_t closed = 0, branched = 0;
    for (const json& c : d["contours"]) {
      length += c["length"].get<double>();
      if (c["closed"].get<bool>()) {
        ++closed;
        areas.push_back(c["area"].get<double>());
      }
    }
    const double want = oracle["length"].get<double>();
    // The oracle's flattening may shorten curves by its stated slack, never lengthen them.
    EXPECT_NEAR(length, want, 1e-7 * want + oracle["length_slack"].get<double>() + 1e-6) << file_;

    // Chaining, where the graph of ends does not branch.
    if (oracle["branch_nodes"].get<int>() == 0) {
      EXPECT_EQ(d["contours"].size(), oracle["components"].get<std::size_t>()) << file_;
      EXPECT_EQ(closed, oracle["loops"].get<std::size_t>()) << file_;
      const std::vector<double> theirs = oracle["loop_areas"].get<std::vector<double>>();
      const std::vector<double> slack = oracle["loop_area_slack"].get<std::vector<double>>();
      std::sort(areas.begin(), areas.end());
      ASSERT_EQ(areas.size(), theirs.size());
      for (std::size_t i = 0; i < areas.size(); ++i)
        EXPECT_NEAR(areas[i], theirs[i], 1e-7 * theirs[i] + slack[i] + 1e-9) << i;
    } else {
      ++branched;
    }
    std::printf("%s: %zu contours (%zu closed), length %.4f mm (ezdxf %.4f)%s\n", name.c_str(), d["contours"].size(),
                closed, length, want, branched ? "; ends branch: chaining compared by length only" : "");
  }

 private:
  fs::path file_;
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const fs::path dir = fs::path(KERF_REALWORLD_DIR) / "dxf";
  if (fs::is_directory(dir))  // the corpus lives beside the project
    for (const fs::path& f : kerf::test::sortedEntries(dir, false, ".dxf")) {
      std::string name = f.stem().string();
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      testing::RegisterTest("dxf_ezdxf_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [f]() -> testing::Test* { return new DxfAgainstEzdxf(f); });
    }
  return RUN_ALL_TESTS();
}
