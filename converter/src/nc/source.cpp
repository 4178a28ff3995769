#include "kerf/converter/nc/source.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <utility>

namespace kerf::converter {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  const char* const data = text_.data();
  const char* const end = data + text_.size();
  lineStarts_.reserve(text_.size() / 16 + 1);  // a wire program's lines are longer: one growth at most
  lineStarts_.push_back(0);
  if (std::memchr(data, '\r', text_.size()) == nullptr) {  // LF only: memchr finds each
    for (const char* p = data; (p = static_cast<const char*>(std::memchr(p, '\n', end - p))) != nullptr;)
      lineStarts_.push_back(static_cast<std::uint32_t>(++p - data));
    return;
  }
  for (const char* p = data; p < end; ++p)
    if (*p == '\n' || (*p == '\r' && (p + 1 == end || p[1] != '\n')))
      lineStarts_.push_back(static_cast<std::uint32_t>(p + 1 - data));
}

SourceLocation SourceFile::locate(std::uint32_t offset) const {
  const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(it - lineStarts_.begin());  // 1-based
  return {line, offset - lineStarts_[line - 1] + 1};
}

std::string_view SourceFile::lineText(std::uint32_t line) const {
  const auto [begin, end] = lineRange(line);
  return text().substr(begin, end - begin);
}

std::string_view trimBlanks(std::string_view s) {
  const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

bool parseNumberField(std::string_view s, double& out) {
  s = trimBlanks(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

}  // namespace kerf::converter
