// tests/bad/*.nc: each file's first line is `; LINE:COL: error: MESSAGE [CODE]`, the first error
// `kerf check` must report. One gtest per file, through the pipeline every command takes (the same
// files also run through the kerf program: cli.bad.*).
#include "kerf/converter/pipeline.h"

#include "data_test_support.h"

#include <gtest/gtest.h>

namespace {

using namespace kerf::converter;

class BadCorpusTest : public testing::Test {
 public:
  explicit BadCorpusTest(std::filesystem::path file) : file_(std::move(file)) {}
  void TestBody() override {
    const std::string text = kerf::test::readFile(file_);
    const std::string firstLine = text.substr(0, text.find('\n'));
    ASSERT_EQ(firstLine.rfind("; ", 0), 0u) << "first line must hold the expected diagnostic";
    const std::string expected = firstLine.substr(2);
    const Pipeline p = runPipeline({file_.filename().string(), text}, {});
    ASSERT_TRUE(p.diags.hasErrors()) << "no error reported";
    for (const Diagnostic& d : p.diags.all()) {
      if (d.severity != Severity::Error) continue;
      ASSERT_FALSE(d.span.isWholeFile()) << "the first error has no place in the file: " << d.message;
      const SourceLocation loc = p.source->locate(d.span.offset);
      const std::string got = std::to_string(loc.line) + ":" + std::to_string(loc.column) + ": error: " + d.message +
                              " [" + codeName(d.code) + "]";
      EXPECT_EQ(got, expected);
      return;
    }
  }

 private:
  std::filesystem::path file_;
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const auto files = kerf::test::sortedEntries(KERF_BAD_DIR, false, ".nc");
  for (const auto& f : files) {
    testing::RegisterTest("bad_corpus_test", f.stem().string().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [f]() -> testing::Test* { return new BadCorpusTest(f); });
  }
  if (files.size() < 25) {
    std::fprintf(stderr, "bad corpus has only %zu files (at least 25 expected)\n", files.size());
    return 1;
  }
  return RUN_ALL_TESTS();
}
