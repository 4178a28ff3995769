// Shared by the data-driven tests: file reading, running the kerf program, capped diffs.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace kerf::test {

/// What a shell command wrote to standard output, and its exit status (-1: it did not exit).
struct CommandRun {
  std::string out;
  int status = -1;
};
inline CommandRun runCommand(const std::string& command) {
  CommandRun r;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
    const int status = pclose(p);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return r;
}

inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

inline std::vector<std::string> splitLines(const std::string& s) {
  std::vector<std::string> lines;
  std::istringstream in(s);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The first differing lines of two texts, at most `cap` of them, as "-expected / +actual".
inline std::string cappedDiff(const std::string& expected, const std::string& actual, std::size_t cap = 12) {
  const auto e = splitLines(expected), a = splitLines(actual);
  std::string out;
  std::size_t shown = 0;
  for (std::size_t i = 0; i < std::max(e.size(), a.size()) && shown < cap; ++i) {
    const std::string* el = i < e.size() ? &e[i] : nullptr;
    const std::string* al = i < a.size() ? &a[i] : nullptr;
    if (el && al && *el == *al) continue;
    out += "line " + std::to_string(i + 1) + ":\n";
    if (el) out += "  - " + *el + "\n";
    if (al) out += "  + " + *al + "\n";
    ++shown;
  }
  if (shown == cap) out += "  ... (more differences not shown)\n";
  return out;
}

inline std::vector<std::filesystem::path> sortedEntries(const std::filesystem::path& dir, bool directories,
                                                        const std::string& extension = {}) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (directories ? e.is_directory() : (e.is_regular_file() && e.path().extension() == extension))
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace kerf::test
