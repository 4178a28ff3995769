// Source text and positions in it.
//
// The text is kept exactly as read; nothing rewrites it (no in-place lowercasing). Positions are
// byte offsets; lines and columns are 1-based, columns count bytes. A line ends at LF, at CR LF
// or at a lone CR (old Mac and some controllers' files), so every reader counts lines alike.
#pragma once

#include "kerf/geometry/memory.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
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

/// Bytes a TextBytes reads where someone else keeps them (a file mapped into memory, see
/// kept()): given back when it is destroyed.
class TextKeeper {
 public:
  virtual ~TextKeeper() = default;
};

/// A text's bytes as a SourceFile keeps them. A long one lies on whole 2 MiB pages of its own
/// (geometry::LargeAllocator), and a reader can fill it where it lies (ofSize, writable) instead of
/// through a string: one copy from the system, no bytes cleared first. Or the bytes are kept
/// elsewhere (kept(): a file mapped read-only, no copy at all). A NUL byte follows the last, as in
/// a std::string. Made implicitly from a string, which it copies; a copy of kept bytes is its own.
class TextBytes {
 public:
  TextBytes() : bytes_(1, '\0') {}
  TextBytes(std::string_view text);  // NOLINT: implicit, as a string converts to a view
  TextBytes(const std::string& text) : TextBytes(std::string_view(text)) {}  // NOLINT
  TextBytes(const char* text) : TextBytes(std::string_view(text)) {}         // NOLINT
  TextBytes(const TextBytes& other) : TextBytes(other.view()) {}
  TextBytes(TextBytes&& other) noexcept;
  TextBytes& operator=(const TextBytes& other);
  TextBytes& operator=(TextBytes&& other) noexcept;
  ~TextBytes() = default;
  /// n bytes for the caller to write through writable() before any is read.
  static TextBytes ofSize(std::size_t n);
  /// The n bytes at `at`, followed by a NUL, read where they lie for as long as `keeper` lives
  /// (it is destroyed with the last of them). Read only: data() gives them only as const.
  static TextBytes kept(const char* at, std::size_t n, std::unique_ptr<TextKeeper> keeper);
  /// The bytes to write (ofSize); nullptr for kept bytes.
  [[nodiscard]] char* writable() { return keeper_ ? nullptr : bytes_.data(); }
  [[nodiscard]] const char* data() const { return keeper_ ? kept_.data() : bytes_.data(); }
  [[nodiscard]] std::size_t size() const { return keeper_ ? kept_.size() : bytes_.size() - 1; }
  [[nodiscard]] std::string_view view() const { return {data(), size()}; }
  /// Keeps the first n bytes (n <= size()).
  void shrink(std::size_t n);

 private:
  std::vector<char, geometry::FillLaterAllocator<char>> bytes_;
  std::string_view kept_;  // the bytes keeper_ keeps (when there is one)
  std::unique_ptr<TextKeeper> keeper_;
};

class SourceFile {
 public:
  /// Largest text accepted (offsets are 32-bit).
  static constexpr std::size_t kMaxSize = 1u << 31;

  SourceFile(std::string name, TextBytes text);

  [[nodiscard]] const std::string& name() const { return name_; }
  /// The text. After releaseText() the first call reads the file again (see there).
  [[nodiscard]] std::string_view text() const {
    if (released_) reload();
    return text_.view();
  }
  [[nodiscard]] SourceLocation locate(std::uint32_t offset) const;
  /// The text of a 1-based line, without its line break.
  [[nodiscard]] std::string_view lineText(std::uint32_t line) const;
  /// Byte offsets [begin, end) of a 1-based line, without its line break.
  [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> lineRange(std::uint32_t line) const;
  [[nodiscard]] std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }

  /// Reads the text again: what the file holds now, or nothing when it cannot be read.
  using TextSource = std::function<std::optional<TextBytes>()>;
  /// Gives the text's memory back while positions (locate, lineCount) stay known: for a long
  /// program whose text is needed again only to quote a diagnostic's line. The first later use of
  /// the text calls `readAgain`; text that is not the same bytes (size or a 64-bit hash differ)
  /// gives blank lines of the old lengths instead, and changedOnDisk() says so. Not thread-safe:
  /// the reading again happens in a const accessor.
  void releaseText(TextSource readAgain);
  [[nodiscard]] bool released() const { return released_; }
  /// The text was read again after releaseText() and the file had changed.
  [[nodiscard]] bool changedOnDisk() const { return changed_; }

 private:
  std::string name_;
  void reload() const;

  mutable TextBytes text_;
  // Written in full where made (FillLaterAllocator: the resize clears nothing before; its pages are
  // small ones from malloc below 1 MiB: a fresh 2 MiB page can cost more than 200 small ones, see
  // geometry/memory.h).
  std::vector<std::uint32_t, geometry::FillLaterAllocator<std::uint32_t>> lineStarts_;
  std::size_t size_ = 0;
  // After releaseText(): how to read the text again, and what it must be.
  TextSource readAgain_;
  std::uint64_t hash_ = 0;
  mutable bool released_ = false;
  mutable bool changed_ = false;
};

}  // namespace kerf::converter
