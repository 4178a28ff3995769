// Source text and positions in it.
//
// The text is kept exactly as read; nothing rewrites it (no in-place lowercasing). Positions are
// byte offsets; lines and columns are 1-based, columns count bytes. A line ends at LF, at CR LF
// or at a lone CR (old Mac and some controllers' files), so every reader counts lines alike.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kerf::converter {

struct SourceSpan {
  std::uint32_t offset = 0;
  std::uint32_t length = 0;

  /// A span that stands for the whole file (a finding about the program, not one place).
  static constexpr SourceSpan wholeFile() { return {0xFFFFFFFFu, 0}; }
  [[nodiscard]] constexpr bool isWholeFile() const { return offset == 0xFFFFFFFFu; }
};

struct SourceLocation {
  std::uint32_t line = 0;    ///< 1-based
  std::uint32_t column = 0;  ///< 1-based, in bytes
};

class SourceFile {
 public:
  /// Largest text accepted (offsets are 32-bit).
  static constexpr std::size_t kMaxSize = 1u << 31;

  SourceFile(std::string name, std::string text);

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] std::string_view text() const { return text_; }
  [[nodiscard]] SourceLocation locate(std::uint32_t offset) const;
  /// The text of a 1-based line, without its line break.
  [[nodiscard]] std::string_view lineText(std::uint32_t line) const;
  /// Byte offsets [begin, end) of a 1-based line, without its line break; {0, 0} for a line the
  /// file does not have. Inline: the parser asks for every line.
  [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> lineRange(std::uint32_t line) const {
    if (line == 0 || line > lineStarts_.size()) return {0, 0};
    const std::uint32_t begin = lineStarts_[line - 1];
    std::uint32_t end = line < lineStarts_.size() ? lineStarts_[line] : static_cast<std::uint32_t>(text_.size());
    // Drop the line break: LF, CR LF or CR.
    if (end > begin && text_[end - 1] == '\n') --end;
    if (end > begin && text_[end - 1] == '\r') --end;
    return {begin, end};
  }
  [[nodiscard]] std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }
  /// The 1-based line that holds byte `offset` (locate's line): a binary search.
  [[nodiscard]] std::uint32_t lineOf(std::uint32_t offset) const { return locate(offset).line; }
  /// lineOf for a reader that walks the text forwards: `hint` is a line to try first (the answer
  /// before; 0 for none), and the line after it; elsewhere a binary search. `hint` is set to the
  /// answer. Inline: the interpreter asks for every block's line.
  [[nodiscard]] std::uint32_t lineOf(std::uint32_t offset, std::uint32_t& hint) const {
    const std::uint32_t* const starts = lineStarts_.data();
    const std::size_t count = lineStarts_.size();
    // Past the start of the hint's line (a hint of 0 wraps to no line), on it or on the next.
    if (const std::uint32_t line = hint; line - 1u < count && starts[line - 1] <= offset) {
      if (line == count || offset < starts[line]) return line;
      if (line + 1 == count || offset < starts[line + 1]) return hint = line + 1;
    }
    return hint = lineOf(offset);
  }

 private:
  std::string name_;
  std::string text_;
  std::vector<std::uint32_t> lineStarts_;  ///< byte offset of each line's first byte
};

/// s without the blanks (space, tab, CR, LF, VT, FF) at either end.
std::string_view trimBlanks(std::string_view s);

/// A field that holds one decimal number and nothing else but blanks around it and a leading '+'
/// (std::from_chars's grammar otherwise): true with the value in `out`; false for anything else, and
/// for a number that is not finite. The drawing and curve readers and offset tables read their
/// numbers with it.
bool parseNumberField(std::string_view field, double& out);

}  // namespace kerf::converter
