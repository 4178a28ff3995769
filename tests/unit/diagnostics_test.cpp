// The table of diagnostic codes (diagnostic_table.h): one row per code, in ascending order, each in
// its family's hundreds, and docs/diagnostics.md made from it.
#include "kerf/converter/nc/diagnostics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
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
    EXPECT_LT(number, 1000u) << c.name;
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

// Every place in the sources that raises a code with a severity written beside it
// (`diags.warning(Code::X`, `finding(Severity::Note, Code::X`) raises it with a severity the table
// documents for it, so that docs/diagnostics.md and SARIF's rules say what users see.
TEST(diagnostics_test, every_raise_site_uses_a_severity_the_table_documents) {
  std::map<std::string, const CodeInfo*, std::less<>> byName;
  for (const CodeInfo& c : diagnosticCodes()) byName[std::string(c.name)] = &c;
  const std::regex call(R"(\b(error|warning|note)\(\s*Code::(\w+))");
  const std::regex given(R"(Severity::(Note|Warning|Error),\s*Code::(\w+))");
  std::size_t sites = 0;
  for (const char* folder : {"/converter/src", "/viewer/src"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(KERF_SOURCE_DIR + std::string(folder))) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".h") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      const std::string source = text.str();
      for (const std::regex* pattern : {&call, &given}) {
        for (auto it = std::sregex_iterator(source.begin(), source.end(), *pattern); it != std::sregex_iterator();
             ++it) {
          ++sites;
          std::string severity = (*it)[1];
          severity[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(severity[0])));
          const auto row = byName.find((*it)[2].str());
          const auto line = std::count(source.begin(), source.begin() + it->position(), '\n') + 1;
          ASSERT_NE(row, byName.end()) << entry.path() << ":" << line;
          EXPECT_NE(row->second->severityText.find(severity), std::string_view::npos)
              << entry.path().string() << ":" << line << ": " << codeName(row->second->code) << " raised as "
              << severity << ", documented as \"" << row->second->severityText << "\"";
        }
      }
    }
  }
  EXPECT_GT(sites, 200U) << "the patterns no longer find the raise sites";
}

}  // namespace
