// Program: the blocks of an ISO (RS-274 / ISO 6983) NC text, word by word, with positions.
//
// The parser checks only what one block can tell (syntax, numbers, repeated words); what the
// words mean is the interpreter's job (interpreter.h). docs/formats.md describes the syntax read.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <vector>

namespace kerf::converter {

/// std::lround inline (the readers round every G and M word): the same value for every finite
/// |v| < 2^62, else lround's.
inline long roundHalfAway(double v) {
  if (!(v < 4.6e18 && v > -4.6e18)) return std::lround(v);
  long t = static_cast<long>(v);                // towards zero
  const double f = v - static_cast<double>(t);  // exact: |v| < 2^52, or v is whole and f is 0
  if (f >= 0.5)
    ++t;
  else if (f <= -0.5)
    --t;
  return t;
}

/// What stands after a word's letter.
enum class WordValue : std::uint8_t {
  Number,     ///< a number: Word::value
  Bare,       ///< nothing: an axis letter alone after G28 / G30 (`G28 X Y U V`: home these axes)
  Direction,  ///< a sign alone (`Y+`, Sodick edge sensing): Word::value is +1 or -1
  Register,   ///< a register expression (`XH111 + H112`, Sodick): known only at the machine
  Macro,      ///< a macro B value (`X#100`, `X[#1+2]`): known only at the machine
};

struct Word {
  char letter = 0;  ///< upper case A-Z
  // One byte for both, so that a word stays 16 bytes (a program holds millions of them).
  bool hasPoint : 1 = false;               ///< the number was written with a decimal point
  WordValue kind : 3 = WordValue::Number;  ///< what the value is
  /// Written after a comma: Fanuc's optional corner words `,R r` (round the corner at the block's
  /// end) and `,C c` (chamfer it). The span starts at the comma.
  bool corner : 1 = false;
  /// A G word written as digits (no point) that names a code of the motion group, G00-G03: 1 + its
  /// code (GCode), as the parse found it in the G-code table, so that the interpreter need not look
  /// it up again; 0 in every other word.
  /// (Every bit of the byte is named, so that copying a word writes whole bytes: unnamed, GCC reads
  /// the byte first to keep them.)
  std::uint8_t motionCode : 3 = 0;
  std::uint16_t length = 0;  ///< bytes of the whole word in the source (letter + value)
  std::uint32_t offset = 0;  ///< byte offset of the letter
  double value = 0.0;        ///< as written (no unit conversion); 0 unless a Number

  [[nodiscard]] SourceSpan span() const { return {offset, length}; }
  [[nodiscard]] bool isNumber() const { return kind == WordValue::Number; }
};
static_assert(sizeof(Word) == 16, "a Word is 16 bytes: a program holds millions of them");

/// A setting line kept verbatim, e.g. a Sodick register `H001 = +000000.1300` or a condition
/// `C000 = ...`, or SKD `E001= ...`. Kerf stores them; it does not interpret them.
struct Setting {
  std::string name;   ///< as written before '=', upper-cased letter + digits
  std::string value;  ///< text after '=', trimmed
  SourceSpan span;
  std::uint32_t line = 0;
};

enum class BlockKind : std::uint8_t {
  Words,      ///< an ordinary block of words
  MacroCall,  ///< a Sodick macro call `QAIC(2,1,...)` or `Q99()LH114`: name and arguments, no words
  MacroB,     ///< a Fanuc macro B statement (`#100 = ...`, `WHILE[...]DO1`, `END1`, `IF`, `GOTO`)
};

struct Block {
  /// The longest line the parser reads (K0114 refuses a longer one): a block's length, word count
  /// and upperFrom are 16 bits, so that a block is 16 bytes (a program holds one per line; they
  /// are held with the moves while the program runs). A word is two characters at least, so a
  /// block of a line this long holds fewer than kMaxLength words.
  static constexpr std::size_t kMaxLength = 0xFFFF;

  std::uint32_t firstWord = 0;  ///< index in Program::words, or in Program::plainWords for a plain block
  std::uint32_t offset = 0;     ///< start of the block's text; its line is SourceFile::lineOf(offset)
  std::uint16_t length = 0;     ///< to the end of the block's text (without the line break)
  std::uint16_t wordCount = 0;
  /// Words from this index on (relative to firstWord) describe the upper contour. The parser
  /// orders a block's words so that the lower side's come first: those before a Sodick ':' or a
  /// second motion word after a coordinate (`G2 X Y I J G1 U V`, cnc3) in the order written;
  /// otherwise by letter — U V K L, and a second I J or R, belong to the upper side, whatever the
  /// order (RS274 gives word order no meaning). Equal to wordCount when the block has no upper side.
  std::uint16_t upperFrom = 0;
  BlockKind kind = BlockKind::Words;
  bool colon : 1 = false;          ///< the upper side was opened with ':'
  bool twoMotions : 1 = false;     ///< the upper side was opened by a second motion word (cnc3)
  bool blockDelete : 1 = false;    ///< started with '/'
  bool hasError : 1 = false;       ///< the parser reported an error in this block
  bool lowerCase : 1 = false;      ///< some word letter was written in lower case
  bool unusualValues : 1 = false;  ///< some word's value is not a number (WordValue other than Number)
  /// Words only, every one X Y I J R F or a motion code G00-G03, all numbers, none written in
  /// lower case, one side, no error: nothing the whole-program scans look for (machine and dialect
  /// evidence, labels, calls, polar and rotary words), so they pass such a block by. Most blocks
  /// of a wire program are. Its words are kept in Program::plainWords.
  bool plain : 1 = false;
  std::uint8_t unusedBit : 1 = 0;  ///< named so that copying a block writes whole bytes (see Word)
  [[nodiscard]] SourceSpan span() const { return {offset, length}; }
};
static_assert(sizeof(Block) == 16, "a Block is 16 bytes: a program holds one per line");

/// A plane height written in the program outside the word set (docs/taper.md): Sodick `TP` /
/// `TN` words and LinuxCNC `(AXIS,XY_Z_POS,z)` / `(AXIS,UV_Z_POS,z)` comments.
struct HeightWord {
  enum class Kind : std::uint8_t { SodickProgramPlane, SodickLowerPlane, LinuxCncXyPlane, LinuxCncUvPlane } kind{};
  double value = 0.0;  ///< as written (no unit conversion)
  bool hasPoint = true;
  SourceSpan span;
  std::uint32_t line = 0;
};

/// How a machine's text is split into blocks (its profile says, machine.h).
struct ParseOptions {
  /// true: `;` ends a block and what follows on the line is another block (Sodick);
  /// false: `;` starts a comment that runs to the end of the line (LinuxCNC, most controls).
  bool semicolonEndsBlock = false;
  /// The second plane's axes are named U Z: read Z as V (some hot-wire firmware).
  bool upperAxesUZ = false;

  bool operator==(const ParseOptions&) const = default;
};

/// The words of the plain blocks (Block::plain), apart from the others' so that a long program's
/// can be given back as it runs: the parse reads each number once and the interpreter reads the
/// words kept. They are kept in chunks of kChunkWords words, a block's words in one chunk, which
/// the one reader that passes every block in order (the interpreter) gives back behind it: a long
/// program's words are never all held while its moves are made (at the start of a run they are,
/// with the text and the blocks and no move yet). A block whose chunk was given back is parsed
/// again by WordReader, to the same words: giving back changes no answer, which is why it may be
/// done through a const Program. Not for readers on several threads at once.
class PlainWords {
 public:
  /// Each chunk spans this many indices; the first ones hold fewer words (capacityOf), so that a
  /// program of one block (`kerf explain` parses each block alone) does not take a megabyte.
  static constexpr std::uint32_t kChunkWords = std::uint32_t{1} << 16;
  static constexpr std::uint32_t capacityOf(std::size_t chunk) {
    return chunk >= 6 ? kChunkWords : std::uint32_t{1024} << chunk;
  }

  /// Room for up to n (at most kChunkWords) words in one chunk, at index `at()`: the parse writes
  /// a block's words there, then keeps them (keep) or not (the room is used by the next block).
  Word* room(std::size_t n) {
    const std::size_t chunk = size_ / kChunkWords, at = size_ % kChunkWords;
    if (at + n <= capacityOf(chunk) && chunk < chunks_.size() && chunks_[chunk]) return chunks_[chunk].get() + at;
    return roomInAnotherChunk(n);
  }
  /// No word, the first chunk kept for the next (WordReader's block parsed again).
  void clear();
  [[nodiscard]] std::uint32_t at() const { return size_; }
  void keep(std::size_t n) { size_ += static_cast<std::uint32_t>(n); }
  /// The words from index `first`; null when their chunk was given back.
  [[nodiscard]] const Word* find(std::uint32_t first) const {
    const std::size_t chunk = first / kChunkWords;
    return chunk < chunks_.size() && chunks_[chunk] ? chunks_[chunk].get() + first % kChunkWords : nullptr;
  }
  /// Gives back the chunks before the one that holds index `first`.
  void giveBackBefore(std::uint32_t first) const {
    for (const std::size_t chunk = first / kChunkWords; givenBack_ < chunk && givenBack_ < chunks_.size();)
      chunks_[givenBack_++].reset();
  }

 private:
  Word* roomInAnotherChunk(std::size_t n);
  /// A chunk's memory, allocated and not written: a Word (an aggregate) begins its life there when
  /// the parse writes it.
  struct FreeChunk {
    void operator()(Word* words) const noexcept { ::operator delete(words); }
  };
  using Chunk = std::unique_ptr<Word, FreeChunk>;

  mutable std::vector<Chunk> chunks_;
  mutable std::size_t givenBack_ = 0;  ///< chunks before this are given back
  std::uint32_t size_ = 0;             ///< index of the next word
};

struct Program {
  const SourceFile* source = nullptr;
  /// The words of the blocks that are not plain, in order.
  std::vector<Word> words;
  /// The words of the plain blocks.
  PlainWords plainWords;
  /// Only blocks with at least one word, a macro statement or an error.
  std::vector<Block> blocks;
  std::vector<Setting> settings;
  std::vector<HeightWord> heights;
  bool anyDecimalPoint = false;          ///< some length word was written with a decimal point
  double largestInteger = 0.0;           ///< largest |value| of a length word written without a point
  Word largestIntegerWord;               ///< that word (when integerLengthWords > 0)
  std::uint32_t integerLengthWords = 0;  ///< length words written without a decimal point
  /// The blocks that are not plain (Block::plain), in order. A plain block holds no evidence of a
  /// dialect or a machine, no subprogram call, label or mill-turn code: the scans for those go
  /// through these alone (a long program's thousands of moves are plain). parseProgram fills it.
  std::vector<std::uint32_t> notPlain;

  /// The words of a block that is not plain (a plain block's: WordReader, which parses a block
  /// whose kept words were given back again).
  [[nodiscard]] std::span<const Word> wordsOf(const Block& b) const {
    assert(!b.plain);
    return {words.data() + b.firstWord, b.wordCount};
  }
  /// The block's text as written.
  [[nodiscard]] std::string_view textOf(const Block& b) const { return source->text().substr(b.offset, b.length); }
  /// The 1-based line a block starts on (a binary search in the source's lines).
  [[nodiscard]] std::uint32_t lineOf(const Block& b) const { return source->lineOf(b.offset); }
};

/// The words of any block of a program, as the parser read them: a block that is not plain's from
/// Program::words, a plain block's from Program::plainWords, or, where those were given back, from
/// the block's text parsed again by the parser itself (the same words: the same parse). The spans
/// returned stay valid until this reader's next call (and a kept block's until its chunk is given
/// back); a reader reuses one buffer, so reading block after block allocates nothing once it has
/// grown.
class WordReader {
 public:
  explicit WordReader(const Program& program);
  ~WordReader();
  WordReader(const WordReader&) = delete;
  WordReader& operator=(const WordReader&) = delete;

  [[nodiscard]] std::span<const Word> words(const Block& b) {
    if (!b.plain) return program_.wordsOf(b);
    if (const Word* kept = program_.plainWords.find(b.firstWord)) return {kept, b.wordCount};
    return parseAgain(b);
  }
  /// The lower side's words (all of them when the block has no upper side).
  [[nodiscard]] std::span<const Word> lowerWords(const Block& b) { return words(b).first(b.upperFrom); }
  [[nodiscard]] std::span<const Word> upperWords(const Block& b) { return words(b).subspan(b.upperFrom); }

 private:
  struct Again;  // the parser that parses a given-back block again, and its program (program.cpp)
  /// A plain block whose kept words were given back: its text parsed again.
  std::span<const Word> parseAgain(const Block& b);

  const Program& program_;
  std::vector<Word> buffer_;
  std::unique_ptr<Again> again_;  ///< made at the first block given back
};

/// Parses the whole text. Errors go to diags; a block with an error is kept (hasError) so the
/// interpreter can skip it and go on finding more problems. A UTF-8 byte-order mark is skipped;
/// lines end at LF, CR LF or a lone CR.
Program parseProgram(const SourceFile& source, Diagnostics& diags, const ParseOptions& options = {});

}  // namespace kerf::converter
