// tests/golden/<case>/: input.nc, an optional `options` file (`key = value` lines: kerf's options
// without their dashes, e.g. `integer-unit = um`, `step = 0.5`), and what the kerf program gives:
//   expected.trace           `kerf check input.nc --trace`: the toolpath and every diagnostic;
//   expected.bp95d           what `kerf convert input.nc --to bp95d -o -` writes (empty when it
//                            writes nothing), and expected.bp95d.log its exit code and messages;
//   expected.points4(.log)   the same for `--to points4`, for taper programs;
//   expected.3b, .4b, .iso, .polar (and .log)  the same for those emitters (one plane: the lower).
// An emitter's own options (max-points, profile, start-block, plane, pass) go to convert only.
// Each runs the kerf program in the case's folder, so messages name input.nc. Byte compare; a
// capped diff on failure; KERF_UPDATE_GOLDEN=1 rewrites the expectations instead of comparing.
#include "data_test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include <sys/wait.h>

namespace {

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

struct KerfRun {
  int exit = -1;
  std::string out, err;
};

/// Runs kerf in dir with args (already quoted where needed); stdout and stderr captured apart.
KerfRun runKerf(const fs::path& dir, const std::string& args) {
  const fs::path scratch = fs::path(KERF_GOLDEN_WORK) / dir.filename();
  fs::create_directories(scratch);
  const fs::path out = scratch / "stdout", err = scratch / "stderr";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(KERF_PROGRAM) + "' " + args + " > '" +
                              out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  KerfRun r;
  r.exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = kerf::test::readFile(out);
  r.err = kerf::test::readFile(err);
  return r;
}

class GoldenTest : public testing::Test {
 public:
  explicit GoldenTest(fs::path dir) : dir_(std::move(dir)) {}

  void TestBody() override {
    std::string readArgs, emitArgs;
    for (const auto& [key, value] : readOptions(dir_ / "options")) {
      // Sampling and reading options go to every command; the rest to convert.
      const bool emitter =
          key == "max-points" || key == "profile" || key == "start-block" || key == "plane" || key == "pass";
      (emitter ? emitArgs : readArgs) += " --" + key + " '" + value + "'";
    }
    const KerfRun trace = runKerf(dir_, "check input.nc --trace" + readArgs);
    ASSERT_LT(trace.exit, 2) << trace.err;
    compare("expected.trace", trace.out);
    const bool taper = trace.out.find("\ndialect ") != std::string::npos;
    std::string bp95dArgs = "convert input.nc --to bp95d -o -" + readArgs + emitArgs;
    if (taper && emitArgs.find("--plane") == std::string::npos) bp95dArgs += " --plane lower";
    const KerfRun bp95d = runKerf(dir_, bp95dArgs);
    compare("expected.bp95d", bp95d.out);
    compare("expected.bp95d.log", "exit " + std::to_string(bp95d.exit) + "\n" + bp95d.err);
    // The other writers: 3B, 4B and polar follow one plane (the lower of a taper program), ISO and
    // DXF keep both.
    for (const char* to : {"3b", "4b", "iso", "polar", "dxf"}) {
      const bool bothPlanes = std::string(to) == "iso" || std::string(to) == "dxf";
      std::string args = std::string("convert input.nc --to ") + to + " -o -" + readArgs;
      if (taper && !bothPlanes) args += " --plane lower";
      const auto o = readOptions(dir_ / "options");
      if (o.count("start-block") && (std::string(to) == "3b" || std::string(to) == "4b"))
        args += " --start-block '" + o.at("start-block") + "'";
      if (o.count("pass")) args += " --pass '" + o.at("pass") + "'";
      const KerfRun run = runKerf(dir_, args);
      compare(std::string("expected.") + to, run.out);
      compare(std::string("expected.") + to + ".log", "exit " + std::to_string(run.exit) + "\n" + run.err);
    }
    if (taper) {
      std::string points4Args = "convert input.nc --to points4 -o -" + readArgs;
      if (const auto o = readOptions(dir_ / "options"); o.count("profile"))
        points4Args += " --profile '" + o.at("profile") + "'";
      const KerfRun points4 = runKerf(dir_, points4Args);
      compare("expected.points4", points4.out);
      compare("expected.points4.log", "exit " + std::to_string(points4.exit) + "\n" + points4.err);
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
    testing::RegisterTest("golden_test", dir.filename().string().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [dir]() -> testing::Test* { return new GoldenTest(dir); });
  }
  return RUN_ALL_TESTS();
}
