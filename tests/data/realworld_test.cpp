// The real programs in ../shared/realworld (iso2d, xyuv, polar): written by other people for real
// machines, read as their machines meant them.
//
//   realworld.<file>              `kerf check FILE --json` against tests/realworld/expectations.txt:
//                                 machine, dialect, moves, cut length, verdict and the codes
//                                 reported, each decided by hand with the reason written there;
//   realworld.every_file_has_an_expectation
//   realworld_metamorphic.<file>  the same file with other line endings (LF, CR LF, CR), lower-case
//                                 letters, a byte-order mark, no final newline, Shift-JIS bytes in
//                                 comments, the words of single-motion blocks shuffled, and with its
//                                 profile given instead of detected: the same toolpath and findings.
#include "kerf/converter/pipeline.h"
#include "kerf/converter/report/report.h"

#include "data_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using namespace kerf::converter;

const fs::path kRealworld = KERF_REALWORLD_DIR;
constexpr const char* kFolders[] = {"iso2d", "xyuv", "polar"};

struct Expectation {
  std::map<std::string, std::string> fields;
  [[nodiscard]] std::string get(const std::string& key) const {
    const auto it = fields.find(key);
    return it == fields.end() ? std::string{} : it->second;
  }
};

std::vector<Expectation> readExpectations() {
  std::vector<Expectation> out;
  Expectation current;
  for (const std::string& raw : kerf::test::splitLines(kerf::test::readFile(KERF_EXPECTATIONS))) {
    const std::string line = raw.substr(0, raw.find_last_not_of("\r") + 1);
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find(" = ");
    const std::string key = line.substr(0, eq == std::string::npos ? line.find(" =") : eq);
    const std::string value = eq == std::string::npos ? std::string{} : line.substr(eq + 3);
    if (key == "file" && !current.fields.empty()) {
      out.push_back(current);
      current = {};
    }
    current.fields[key] = value;
  }
  if (!current.fields.empty()) out.push_back(current);
  return out;
}

std::string testName(const std::string& file) {
  std::string n = file;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

std::string runKerf(const std::string& args) {
  return kerf::test::runCommand("'" + std::string(KERF_PROGRAM) + "' " + args + " 2>/dev/null").out;
}

class RealworldCheck : public testing::Test {
 public:
  explicit RealworldCheck(Expectation e) : e_(std::move(e)) {}
  void TestBody() override {
    const std::string file = e_.get("file");
    const std::string out = runKerf("check '" + (kRealworld / file).string() + "' " + e_.get("options") +
                                    " --json --max-diagnostics 100000");
    const nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << "kerf check gave no JSON: " << out;
    const auto& s = j["summary"];
    EXPECT_EQ(s["machine"].get<std::string>(), e_.get("machine")) << e_.get("why");
    EXPECT_EQ(s["dialect"].get<std::string>(), e_.get("dialect")) << e_.get("why");
    EXPECT_EQ(s["moves"].get<std::size_t>(), std::stoul(e_.get("moves"))) << e_.get("why");
    EXPECT_NEAR(s["cut_length_mm"].get<double>(), std::stod(e_.get("cut_length")), 1e-3) << e_.get("why");
    EXPECT_EQ(j["verdict"].get<std::string>(), e_.get("verdict")) << e_.get("why");
    std::set<std::string> got, want;
    for (const auto& d : j["diagnostics"]) got.insert(d["code"].get<std::string>());
    std::istringstream codes(e_.get("codes"));
    for (std::string c; codes >> c;) want.insert(c);
    std::string gotText;
    for (const std::string& c : got) gotText += c + " ";
    EXPECT_EQ(got, want) << "codes reported: " << gotText << "\n" << e_.get("why");
  }

 private:
  Expectation e_;
};

// ---- the metamorphic reruns --------------------------------------------------------------------

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
  return s;
}
std::string lf(const std::string& s) { return replaceAll(replaceAll(s, "\r\n", "\n"), "\r", "\n"); }

/// Applies f to every line (LF endings), keeping the line structure.
template <typename F>
std::string eachLine(const std::string& text, F f) {
  std::string out;
  for (const std::string& line : kerf::test::splitLines(lf(text))) out += f(line) + "\n";
  return out;
}

/// Shuffles the words of blocks that are only words, with one motion word and no letter twice:
/// RS274 gives word order no meaning there.
std::string shuffleWords(const std::string& text) {
  std::mt19937 rng(7);
  const std::regex onlyWords(R"(^[A-Za-z0-9.+\- \t]*$)");
  const std::regex word(R"([A-Za-z][+-]?[0-9]*\.?[0-9]*)");
  return eachLine(text, [&](const std::string& line) {
    if (!std::regex_match(line, onlyWords) || line.find_first_not_of(" \t") == std::string::npos) return line;
    std::vector<std::string> words;
    std::string joined;
    std::set<char> letters;
    int motions = 0;
    bool repeated = false;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), word); it != std::sregex_iterator(); ++it) {
      const std::string w = it->str();
      if (w.find_first_of("0123456789") == std::string::npos) repeated = true;  // a keyword (END1), not a word
      words.push_back(w);
      joined += w;
      const char l = static_cast<char>(std::toupper(static_cast<unsigned char>(w[0])));
      if (l == 'G' && w.size() > 1 && std::stod(w.substr(1)) <= 3) ++motions;
      if (l != 'G' && l != 'M' && !letters.insert(l).second) repeated = true;
    }
    std::string compact = line;
    compact.erase(std::remove_if(compact.begin(), compact.end(), [](char c) { return c == ' ' || c == '\t'; }),
                  compact.end());
    if (compact != joined || motions > 1 || repeated || words.size() < 2) return line;
    std::shuffle(words.begin(), words.end(), rng);
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
  });
}

struct Reading {
  std::string toolpath;
  std::set<std::string> codes;
  std::string machine;
};

Reading readWith(const std::string& text, const std::string& options, const std::optional<std::string>& machine) {
  PipelineOptions po;
  if (options.find("--thickness 30") != std::string::npos) po.read.thickness = 30.0;
  po.read.machine = machine;
  const Pipeline p = runPipeline({"program", text}, po);
  Reading r;
  r.toolpath = formatTrace(p.toolpath, Diagnostics(0));
  for (const Diagnostic& d : p.diags.all())
    if (d.code != Code::MachineDetected || !machine) r.codes.insert(codeName(d.code));
  r.machine = p.machine.name;
  return r;
}

class RealworldMetamorphic : public testing::Test {
 public:
  explicit RealworldMetamorphic(Expectation e) : e_(std::move(e)) {}
  void TestBody() override {
    const std::string text = kerf::test::readFile(kRealworld / e_.get("file"));
    const std::string options = e_.get("options");
    const Reading base = readWith(text, options, std::nullopt);
    const std::string sjis = "(\x83\x8F\x83\x43\x83\x84)";  // ワイヤ in Shift-JIS
    const std::pair<const char*, std::string> variants[] = {
        {"LF", lf(text)},
        {"CR LF", replaceAll(lf(text), "\n", "\r\n")},
        {"CR", replaceAll(lf(text), "\n", "\r")},
        {"lower case",
         [&] {
           std::string t = text;
           for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
           return t;
         }()},
        {"byte-order mark", "\xEF\xBB\xBF" + text},
        {"no final newline", text.substr(0, text.find_last_not_of("\r\n") + 1)},
        {"Shift-JIS comments", eachLine(text,
                                        [&](const std::string& line) {
                                          const auto first = line.find_first_not_of(" \t");
                                          if (first == std::string::npos || line[first] == '%' ||
                                              line.find('(') != std::string::npos ||
                                              line.find(';') != std::string::npos)
                                            return line;
                                          return line + " " + sjis;
                                        })},
        {"shuffled words", shuffleWords(text)},
    };
    for (const auto& [what, variant] : variants) {
      const Reading r = readWith(variant, options, std::nullopt);
      EXPECT_EQ(r.toolpath, base.toolpath) << what << ": the toolpath changed";
      EXPECT_EQ(r.codes, base.codes) << what << ": the findings changed";
      EXPECT_EQ(r.machine, base.machine) << what << ": another machine was detected";
    }
    // The profile given instead of detected: the same reading.
    const Reading given = readWith(text, options, base.machine);
    EXPECT_EQ(given.toolpath, base.toolpath) << "--machine " << base.machine << ": the toolpath changed";
    std::set<std::string> baseCodes = base.codes;
    baseCodes.erase("K0230");
    EXPECT_EQ(given.codes, baseCodes) << "--machine " << base.machine << ": the findings changed";
  }

 private:
  Expectation e_;
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  if (!fs::is_directory(kRealworld)) {
    // The corpus lives beside the project (../shared/realworld), not in it. Under CI (CI set and
    // not "false" or "0") its absence is a failure; elsewhere the real programs are skipped.
    testing::RegisterTest("realworld_test", "corpus_present", nullptr, nullptr, __FILE__, __LINE__,
                          []() -> testing::Test* {
                            struct Missing : testing::Test {
                              void TestBody() override {
                                const char* ci = std::getenv("CI");
                                if (ci && *ci && std::string_view(ci) != "false" && std::string_view(ci) != "0")
                                  FAIL() << kRealworld << " is not there: under CI the real programs must be checked";
                                GTEST_SKIP() << kRealworld << " is not there: the real programs are not checked";
                              }
                            };
                            return new Missing;
                          });
    return RUN_ALL_TESTS();
  }
  const std::vector<Expectation> expectations = readExpectations();
  for (const Expectation& e : expectations) {
    const std::string name = testName(e.get("file"));
    testing::RegisterTest("realworld_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [e]() -> testing::Test* { return new RealworldCheck(e); });
    testing::RegisterTest("realworld_metamorphic_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [e]() -> testing::Test* { return new RealworldMetamorphic(e); });
  }
  testing::RegisterTest("realworld_test", "every_file_has_an_expectation", nullptr, nullptr, __FILE__, __LINE__,
                        [expectations]() -> testing::Test* {
                          struct Every : testing::Test {
                            std::vector<Expectation> e;
                            explicit Every(std::vector<Expectation> x) : e(std::move(x)) {}
                            void TestBody() override {
                              std::set<std::string> listed;
                              for (const Expectation& x : e) listed.insert(x.get("file"));
                              std::size_t files = 0;
                              for (const char* folder : kFolders)
                                for (const auto& f : fs::directory_iterator(kRealworld / folder)) {
                                  const std::string rel = std::string(folder) + "/" + f.path().filename().string();
                                  ++files;
                                  EXPECT_TRUE(listed.count(rel)) << rel << " has no entry in expectations.txt";
                                }
                              EXPECT_EQ(files, listed.size()) << "expectations.txt lists files that are not there";
                            }
                          };
                          return new Every(expectations);
                        });
  return RUN_ALL_TESTS();
}
