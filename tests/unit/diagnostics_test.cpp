// The table of diagnostic codes (diagnostic_table.h): one row per code, in ascending order, each in
// its family's hundreds, and docs/diagnostics.md made from it.
#include "kerf/converter/nc/diagnostics.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {

using kerf::converter::Code;
using kerf::converter::CodeInfo;
using kerf::converter::codeInfo;
using kerf::converter::codeName;
using kerf::converter::diagnosticCodes;
using kerf::converter::Severity;
using kerf::converter::severityName;

TEST(diagnostics_test, codes_are_unique_ascending_and_in_their_family) {
  std::set<std::string_view> names;
  unsigned previous = 0;
  for (const CodeInfo& c : diagnosticCodes()) {
    const auto number = static_cast<unsigned>(c.code);
    EXPECT_GT(number, previous) << codeName(c.code) << " after K" << previous << ": the table must ascend";
    previous = number;
    EXPECT_GE(number, 100u) << c.name;
    EXPECT_LT(number, 900u) << c.name;
    EXPECT_NE(number % 100, 0u) << codeName(c.code) << ": xx00 is a family's name, not a code";
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
    EXPECT_FALSE(c.meaning.empty()) << c.name;
    // The documented words start with the default severity ("note/warning" is a note by default).
    EXPECT_TRUE(c.severityText.starts_with(severityName(c.severity))) << c.name << ": " << c.severityText;
    EXPECT_EQ(&codeInfo(c.code), &c) << c.name;
  }
  EXPECT_GT(diagnosticCodes().size(), 100u);
  EXPECT_EQ(codeInfo(Code::RadiusTooSmall).name, "RadiusTooSmall");
  EXPECT_EQ(codeName(Code::RadiusTooSmall), "K0302");
}

TEST(diagnostics_test, the_documented_table_is_made_from_the_code_table) {
  const std::string path = KERF_DOCS_DIR "/diagnostics.md";
  const std::string made = kerf::converter::diagnosticsMarkdown();
  if (const char* u = std::getenv("KERF_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::ofstream(path, std::ios::binary) << made;
    GTEST_SKIP() << "rewrote " << path;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_EQ(doc.str(), made) << path << " differs from the table: KERF_UPDATE_GOLDEN=1 rewrites it";
  for (const CodeInfo& c : diagnosticCodes())
    EXPECT_NE(doc.str().find("| " + codeName(c.code) + " | " + std::string(c.name) + " |"), std::string::npos)
        << c.name;
}

}  // namespace
