// The multi-pass corpus (tests/passes/*.nc) through the kerf program: each file states, in `;`
// comment lines, the exit status `kerf check` must give (`; expect exit: N`) and lines its pass
// table must hold (`; expect: TEXT`, each a part of one printed line). The lengths in them were
// worked out by hand from the drawing and the offsets (docs/passes.md).
#include "data_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

struct CheckRun {
  std::string out;
  int status = -1;
};

CheckRun checkProgram(const fs::path& file) {
  const std::string command = "'" + std::string(KERF_PROGRAM) + "' check '" + file.string() + "' 2>/dev/null";
  CheckRun r;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
    const int status = pclose(p);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return r;
}

class PassTable : public testing::Test {
 public:
  explicit PassTable(fs::path file) : file_(std::move(file)) {}
  void TestBody() override {
    std::vector<std::string> expected;
    int exitStatus = -1;
    for (const std::string& line : kerf::test::splitLines(kerf::test::readFile(file_))) {
      if (line.starts_with("; expect exit: ")) exitStatus = std::stoi(line.substr(15));
      if (line.starts_with("; expect: ")) expected.push_back(line.substr(10));
    }
    ASSERT_GE(exitStatus, 0) << file_ << " states no '; expect exit: N'";
    ASSERT_FALSE(expected.empty()) << file_ << " states no '; expect:' line";
    const CheckRun r = checkProgram(file_);
    EXPECT_EQ(r.status, exitStatus) << r.out;
    for (const std::string& e : expected)
      EXPECT_NE(r.out.find(e), std::string::npos) << "missing: " << e << "\n" << r.out;
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

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  registerCorpus();
  return RUN_ALL_TESTS();
}
