// Program: the blocks of an ISO (RS-274 / ISO 6983) NC text, word by word, with positions.
//
// The parser checks only what one block can tell (syntax, numbers, repeated words); what the
// words mean is the interpreter's job (interpreter.h).
#pragma once

#include "kerf/converter/diagnostics.h"
#include "kerf/converter/source.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace kerf::converter {

struct Word {
  char letter = 0;           ///< upper case A-Z
  bool hasPoint = false;     ///< the number was written with a decimal point
  std::uint16_t length = 0;  ///< bytes of the whole word in the source (letter + number)
  std::uint32_t offset = 0;  ///< byte offset of the letter
  double value = 0.0;        ///< as written (no unit conversion)

  [[nodiscard]] SourceSpan span() const { return {offset, length}; }
};

/// A setting line kept verbatim, e.g. a Sodick register `H001 = +000000.1300` or a condition
/// `C000 = ...`, or SKD `E001= ...`. Kerf stores them; it does not interpret them.
struct Setting {
  std::string name;   ///< as written before '=', upper-cased letter + digits
  std::string value;  ///< text after '=', trimmed
  SourceSpan span;
  std::uint32_t line = 0;
};

struct Block {
  std::uint32_t firstWord = 0;
  std::uint32_t wordCount = 0;
  std::uint32_t offset = 0;  ///< start of the line
  std::uint32_t length = 0;  ///< to the end of the block's text (without the line break)
  std::uint32_t line = 0;    ///< 1-based
  /// Words from this index on (relative to firstWord) describe the upper contour: those after a
  /// Sodick ':', or from the first U/V word, or from a second motion G after a coordinate
  /// (FORMATS.md §2). Equal to wordCount when the block has no upper side.
  std::uint32_t upperFrom = 0;
  bool colon = false;        ///< the upper side was opened with ':'
  bool blockDelete = false;  ///< started with '/'
  bool hasError = false;     ///< the parser reported an error in this block
  [[nodiscard]] SourceSpan span() const { return {offset, length}; }
};

/// A plane height written in the program outside the word set (FORMATS.md §2): Sodick `TP` /
/// `TN` words and LinuxCNC `(AXIS,XY_Z_POS,z)` / `(AXIS,UV_Z_POS,z)` comments.
struct HeightWord {
  enum class Kind : std::uint8_t { SodickProgramPlane, SodickLowerPlane, LinuxCncXyPlane, LinuxCncUvPlane } kind{};
  double value = 0.0;  ///< as written (no unit conversion)
  bool hasPoint = true;
  SourceSpan span;
  std::uint32_t line = 0;
};

struct Program {
  const SourceFile* source = nullptr;
  std::vector<Word> words;
  std::vector<Block> blocks;  ///< only blocks with at least one word
  std::vector<Setting> settings;
  std::vector<HeightWord> heights;
  bool anyDecimalPoint = false;          ///< some coordinate word was written with a decimal point
  double largestInteger = 0.0;           ///< largest |value| of a length word written without a point
  std::uint32_t largestIntegerWord = 0;  ///< index of that word in words

  [[nodiscard]] std::span<const Word> wordsOf(const Block& b) const {
    return {words.data() + b.firstWord, b.wordCount};
  }
  [[nodiscard]] std::span<const Word> lowerWordsOf(const Block& b) const {
    return {words.data() + b.firstWord, b.upperFrom};
  }
  [[nodiscard]] std::span<const Word> upperWordsOf(const Block& b) const {
    return {words.data() + b.firstWord + b.upperFrom, b.wordCount - b.upperFrom};
  }
};

/// Parses the whole text. Errors go to diags; a block with an error is kept (hasError) so the
/// interpreter can skip it and go on finding more problems.
Program parseProgram(const SourceFile& source, Diagnostics& diags);

}  // namespace kerf::converter
