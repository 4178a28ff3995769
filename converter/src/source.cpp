#include "kerf/converter/source.h"

#include <algorithm>
#include <cstring>

namespace kerf::converter {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  lineStarts_.reserve(static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n')) + 1);
  lineStarts_.push_back(0);
  const char* data = text_.data();
  const std::size_t size = text_.size();
  const bool anyReturn = std::memchr(data, '\r', size) != nullptr;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n' || (anyReturn && data[i] == '\r' && (i + 1 == size || data[i + 1] != '\n')))
      lineStarts_.push_back(static_cast<std::uint32_t>(i + 1));
  }
}

SourceLocation SourceFile::locate(std::uint32_t offset) const {
  const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(it - lineStarts_.begin());  // 1-based
  return {line, offset - lineStarts_[line - 1] + 1};
}

std::pair<std::uint32_t, std::uint32_t> SourceFile::lineRange(std::uint32_t line) const {
  if (line == 0 || line > lineStarts_.size()) return {0, 0};
  const std::uint32_t begin = lineStarts_[line - 1];
  std::uint32_t end = line < lineStarts_.size() ? lineStarts_[line] : static_cast<std::uint32_t>(text_.size());
  // Drop the line break: LF, CR LF or CR.
  if (end > begin && text_.data()[end - 1] == '\n') --end;
  if (end > begin && text_.data()[end - 1] == '\r') --end;
  return {begin, end};
}

std::string_view SourceFile::lineText(std::uint32_t line) const {
  const auto [begin, end] = lineRange(line);
  return text().substr(begin, end - begin);
}

}  // namespace kerf::converter
