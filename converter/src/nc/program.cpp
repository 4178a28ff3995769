// ISO block parser.
//
// Sections: 1. characters and numbers  2. values known only at the machine  3. one block
//           4. the sides of a 4-axis block  5. plain blocks' words  6. the whole text
#include "kerf/converter/nc/program.h"

#include "gcode.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace kerf::converter {
namespace {

// ---- 1. characters and numbers --------------------------------------------------------------

/// What a byte is, as bits: one look per character on the common road.
enum CharClass : std::uint8_t {
  kBlank = 1,
  kDigit = 2,
  kPlainLetter = 4,      ///< the letters of Block::plain's words other than G
  kMotionLetter = 8,     ///< G
  kEndsPlainNumber = 16  ///< may follow a number in a plain block: a blank, a word's letter, ';', the line's end
};
constexpr std::array<std::uint8_t, 256> kCharClass = [] {
  std::array<std::uint8_t, 256> t{};
  for (const unsigned char c : {' ', '\t', '\r', '\f', '\v'}) t[c] = kBlank | kEndsPlainNumber;
  for (unsigned char c = '0'; c <= '9'; ++c) t[c] = kDigit;
  for (const unsigned char c : {'X', 'Y', 'I', 'J', 'R', 'F'}) t[c] = kPlainLetter | kEndsPlainNumber;
  t['G'] = kMotionLetter | kEndsPlainNumber;
  for (const unsigned char c : {';', '\n', '\0'}) t[c] = kEndsPlainNumber;
  return t;
}();
bool hasClass(char c, std::uint8_t bits) { return (kCharClass[static_cast<unsigned char>(c)] & bits) != 0; }

bool isDigit(char c) { return hasClass(c, kDigit); }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isLowerLetter(char c) { return c >= 'a' && c <= 'z'; }
char upper(char c) { return isLowerLetter(c) ? static_cast<char>(c - 'a' + 'A') : c; }
bool isBlank(char c) { return hasClass(c, kBlank); }

/// Letters that are words in ISO wire programs. B is not: it belongs to 3B code.
bool isWordLetter(char u) { return u != 'B'; }

/// The letters of Block::plain's words other than G.
bool isPlainLetter(char letter) { return hasClass(letter, kPlainLetter); }

/// A word Block::plain allows: X Y I J R F, or a code of the motion group (G00-G03).
bool isPlainWord(char letter, WordValue kind, double value) {
  if (kind != WordValue::Number) return false;
  if (letter == 'G') return isMotionCode(value);
  return isPlainLetter(letter);
}

/// Letters whose numbers are lengths: they decide --integer-unit evidence.
bool isLengthLetter(char u) { return u == 'X' || u == 'Y' || u == 'U' || u == 'V' || u == 'I' || u == 'J' || u == 'R'; }

/// Axis letters that may stand alone after G28 / G30 (home these axes).
bool isAxisLetter(char u) {
  return u == 'X' || u == 'Y' || u == 'Z' || u == 'U' || u == 'V' || u == 'W' || u == 'A' || u == 'B' || u == 'C';
}

/// Numbers of this many significant digits before the point or more (1e9 and larger) are refused
/// (K0105): no wire machine travels a kilometre.
constexpr std::size_t kLargestDigits = 10;
/// At most this many significant digits before the point.
constexpr int kMaxDigits = 18;

struct NumberScan {
  enum Status { Ok, Missing, TooManyDigits } status = Missing;
  bool hasPoint = false;
  std::size_t end = 0;            ///< one past the last character used
  std::size_t integerDigits = 0;  ///< significant digits before the point
  double value = 0.0;             ///< 0 when the scan was asked not to convert
};

/// 10^k for k = 0..19: each is a double exactly (10^k = 2^k 5^k and 5^19 < 2^53).
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,
                                        1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19};

/// The value of a decimal number read as digits: `whole` its digits as one whole number (wrapped
/// past 19 digits), integerDigits significant digits before the point and fractionDigits after it,
/// its characters after the sign in [first, end). The correctly rounded double nearest the
/// decimal (what std::from_chars gives): a number of at most 19 digits whose digits, read as a
/// whole number m, stay at most 2^53 is m / 10^k (k digits after the point), both operands exact
/// doubles, and IEEE division rounds correctly, so the quotient is the correctly rounded value
/// (Clinger, "How to read floating point numbers accurately", PLDI 1990: the fast path). Longer
/// numbers go to std::from_chars.
[[gnu::always_inline]] inline double decimalValue(std::uint64_t whole, std::size_t integerDigits,
                                                  std::size_t fractionDigits, bool negative, const char* first,
                                                  const char* end) {
  double v = 0.0;
  if (integerDigits + fractionDigits <= 19 && whole <= (std::uint64_t{1} << 53)) {
    v = static_cast<double>(whole) / kExactPowersOfTen[fractionDigits];
  } else {
    // from_chars takes no '+' and no lone '.' after the digits in every library: the digits alone.
    if (end[-1] == '.') --end;
    std::from_chars(first, end, v, std::chars_format::fixed);
  }
  return negative ? -v : v;
}

/// [sign] digits [. digits] in text[pos, limit) — no exponent, no spaces inside. Leading zeros are
/// not significant; more than 18 significant digits before the point are refused. The value is
/// decimalValue's, unless `convert` is false.
[[gnu::always_inline]] inline NumberScan scanNumber(std::string_view text, std::size_t pos, std::size_t limit,
                                                    bool convert = true) {
  NumberScan s;
  const char* const base = text.data();
  const char* p = base + pos;
  const char* const stop = base + limit;
  const bool negative = p < stop && *p == '-';
  if (p < stop && (*p == '+' || *p == '-')) ++p;
  const char* const first = p;
  while (p < stop && *p == '0') ++p;  // leading zeros
  const char* const significant = p;
  // The digits read as a whole number; wraps past 19 digits (then unused).
  std::uint64_t whole = 0;
  for (unsigned d; p < stop && (d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9; ++p) whole = whole * 10 + d;
  s.integerDigits = static_cast<std::size_t>(p - significant);
  bool anyDigit = p > first;
  std::size_t fractionDigits = 0;
  if (p < stop && *p == '.') {
    s.hasPoint = true;
    const char* const point = ++p;
    for (unsigned d; p < stop && (d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9; ++p) whole = whole * 10 + d;
    fractionDigits = static_cast<std::size_t>(p - point);
    anyDigit = anyDigit || p > point;
  }
  s.end = static_cast<std::size_t>(p - base);
  if (!anyDigit) return s;  // Missing
  if (s.integerDigits > static_cast<std::size_t>(kMaxDigits)) {
    s.status = NumberScan::TooManyDigits;
    return s;
  }
  s.status = NumberScan::Ok;
  if (convert) s.value = decimalValue(whole, s.integerDigits, fractionDigits, negative, first, p);
  return s;
}

std::string describeChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u < 0x20 || u >= 0x7f) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", u);
    return std::string("byte ") + buf;
  }
  return std::string("'") + c + "'";
}

/// Does text[i, limit) start with the keyword (case-insensitive)?
bool startsWithKeyword(std::string_view text, std::size_t i, std::size_t limit, std::string_view keyword) {
  if (limit - i < keyword.size()) return false;
  for (std::size_t k = 0; k < keyword.size(); ++k)
    if (upper(text[i + k]) != keyword[k]) return false;
  return true;
}

// ---- 2. values known only at the machine --------------------------------------------------------

/// `H111`, `H111 + H112`, `H104 / 2`: a Sodick register reference and arithmetic on it. Returns
/// the end of the expression, or pos when there is none at pos.
std::size_t scanRegisterExpression(std::string_view text, std::size_t pos, std::size_t limit) {
  auto registerAt = [&](std::size_t i) { return i + 1 < limit && upper(text[i]) == 'H' && isDigit(text[i + 1]); };
  std::size_t i = pos;
  if (i < limit && (text[i] == '+' || text[i] == '-')) ++i;
  if (!registerAt(i)) return pos;
  i += 1;
  while (i < limit && isDigit(text[i])) ++i;
  for (;;) {
    std::size_t j = i;
    while (j < limit && isBlank(text[j])) ++j;
    if (j >= limit || (text[j] != '+' && text[j] != '-' && text[j] != '*' && text[j] != '/')) return i;
    ++j;
    while (j < limit && isBlank(text[j])) ++j;
    if (registerAt(j)) {
      j += 1;
      while (j < limit && isDigit(text[j])) ++j;
    } else {
      const NumberScan n = scanNumber(text, j, limit);
      if (n.status == NumberScan::Missing) return i;
      j = n.end;
    }
    i = j;
  }
}

/// `#100`, `-#5`, `[#1 + 2.5]`: a macro B value. Returns its end, or pos when there is none.
std::size_t scanMacroValue(std::string_view text, std::size_t pos, std::size_t limit) {
  std::size_t i = pos;
  if (i < limit && (text[i] == '+' || text[i] == '-')) ++i;
  if (i < limit && text[i] == '#') {
    ++i;
    const std::size_t digits = i;
    while (i < limit && isDigit(text[i])) ++i;
    return i > digits ? i : pos;
  }
  if (i < limit && text[i] == '[') {
    int depth = 0;
    for (; i < limit; ++i) {
      if (text[i] == '[') ++depth;
      if (text[i] == ']' && --depth == 0) return i + 1;
    }
  }
  return pos;
}

// ---- 3. one block ----------------------------------------------------------------------------

}  // namespace

// The parser of lines, in a namespace of its own: WordReader keeps one (its type has linkage).
namespace line_parser {

/// The macro B statements of some lines: how many, the first one, and the lines they span.
struct MacroTally {
  std::size_t count = 0;
  SourceSpan first;
  std::uint32_t firstLine = 0, lastLine = 0;
};

class LineParser {
 public:
  LineParser(const SourceFile& src, Program& program, Diagnostics& diags, const ParseOptions& options)
      : src_(src), text_(src.text()), program_(program), diags_(diags), options_(options) {}

  /// Parses [begin, end) — one line without its line break: one block, or several when `;` ends
  /// blocks (ParseOptions::semicolonEndsBlock); or a block's span as a parse gave it (WordReader).
  /// The character at `end` is none of a number's (a line break, the NUL after the text, a blank or
  /// a ';'): the short road's scans stop there without comparing with `end`.
  void parseLine(std::size_t begin, std::size_t end, std::uint32_t line) {
    std::size_t i = begin;
    while (i < end) {
      while (i < end && isBlank(text_[i])) ++i;
      if (i >= end) return;
      // The common block first: no setting is plain (its '=' is no plain block's character).
      if (const std::size_t next = tryPlainBlock(i, end); next != i) {
        i = next;
        continue;
      }
      i = parseBlock(i, end, line);
    }
  }

  /// The macro B statements of the lines parsed.
  [[nodiscard]] const MacroTally& macros() const { return macros_; }

 private:
  /// Parses one block that is not plain (tryPlainBlock), from i at its first character; returns
  /// where the next block on this line starts (or end).
  std::size_t parseBlock(std::size_t i, std::size_t end, std::uint32_t line) {
    if (trySetting(i, end, line)) return end;

    Block block;
    block.firstWord = static_cast<std::uint32_t>(program_.words.size());
    block.offset = static_cast<std::uint32_t>(i);
    if (text_[i] == '/') {
      block.blockDelete = true;
      ++i;
      while (i < end && isBlank(text_[i])) ++i;
    }
    std::size_t blockEnd = end;  // the block's text ends here (';' or the end of the line)
    std::size_t next = end;      // the next block starts here
    if (isMacroStatement(i, end)) {
      block.kind = BlockKind::MacroB;
      blockEnd = findBlockEnd(i, end, next);
      noteMacroStatement(i, blockEnd, line);
      finish(block, blockEnd);
      return next;
    }
    if (const std::size_t callEnd = scanMacroCall(i, end); callEnd != i) {
      block.kind = BlockKind::MacroCall;
      blockEnd = findBlockEnd(callEnd, end, next);
      finish(block, blockEnd);
      return next;
    }

    upperLetters_ = false;
    splitAt_ = -1;
    colon_ = false;
    sawCoordinate_ = false;
    sawMotion_ = false;
    homing_ = false;
    while (i < end) {
      const char c = text_[i];
      if (isBlank(c)) {
        ++i;
        continue;
      }
      if (c == '(') {
        const std::size_t close = text_.find(')', i);
        const std::size_t inner = text_.find('(', i + 1);
        if (inner < end && (close == std::string_view::npos || inner < close)) {
          error(block, Code::NestedComment, inner, 1, "'(' inside a comment: comments cannot nest",
                "use [ ] or another character inside the comment");
          break;
        }
        if (close == std::string_view::npos || close >= end) {
          error(block, Code::UnterminatedComment, i, 1, "comment is not closed on its line",
                "add ')' — a comment cannot span lines");
          break;
        }
        readHeightComment(i, close, line);
        i = close + 1;
        continue;
      }
      if (c == ';') {
        endAtSemicolon(i, end, blockEnd, next);
        break;
      }
      if (c == ':') {  // Sodick: the lower contour before, the upper after (docs/taper.md)
        if (splitAt_ >= 0) {
          error(block, Code::UnexpectedCharacter, i, 1,
                colon_ ? "a second ':' in one block" : "':' after the upper contour's words have begun");
          break;
        }
        splitAt_ = wordsSoFar(block);
        colon_ = true;
        ++i;
        continue;
      }
      if (c == ',' && i + 1 < end && (upper(text_[i + 1]) == 'R' || upper(text_[i + 1]) == 'C')) {
        i = parseCornerWord(block, i, end);
        if (block.hasError) break;
        continue;
      }
      if (!isLetter(c)) {
        strayCharacter(block, i, end);
        break;
      }
      if (isLowerLetter(c)) block.lowerCase = true;
      i = parseWord(block, i, end);
      if (block.hasError) break;  // one error per block: what follows is likely noise from it
    }
    if (!block.hasError) assignSides(block);
    finish(block, blockEnd);
    return next;
  }

  /// The short road for the common block (Block::plain): words of an upper-case X Y I J R F, each
  /// once, or a motion-group code (the G-code table's G00-G03) written as digits, each letter
  /// followed at once by [sign] digits [. digits], blanks between the words, up to the end of the
  /// line or a ';'. What it accepts the word loop below would read as the same plain block, with
  /// the same integer-unit evidence and no diagnostic (parser_test holds the two roads equal). It
  /// reads each number once, in the same pass that checks its syntax, and keeps the block's words
  /// in Program::plainWords, where the interpreter's WordReader finds them.
  /// Anything else — a comment, a blank after a letter, lower case, a second motion word after a
  /// coordinate, anything an error — returns begin, and the word loop reads the block.
  std::size_t tryPlainBlock(const std::size_t begin, const std::size_t end) {
    constexpr std::uint16_t kMostWords = 64;  // more: the word loop (a plain block has at most 7 letters and its G's)
    std::uint32_t letters = 0;                // X Y I J R F seen (each may stand once)
    std::uint16_t count = 0;
    bool sawMotion = false, sawCoordinate = false;
    UnitEvidence evidence;
    // The words go where the program keeps them; they are kept only if the block is plain.
    Word* const words = program_.plainWords.room(kMostWords);
    // At `end` stands a line break ('\n', '\r'), the NUL a std::string keeps after its text
    // (SourceFile holds one), or a blank or ';' after a block's span (parseLine): none is a digit,
    // a sign or a point, so the scans below stop there without comparing with `end`.
    const char* const text = text_.data();
    const char* const stop = text + end;
    const char* p = text + begin;
    std::size_t blockEnd = end, next = end;
    for (;;) {
      while (isBlank(*p)) ++p;  // may pass stop over blanks: a '\r' before the '\n', a span's trailing blanks
      if (p >= stop) break;
      const char c = *p;
      if (c == ';') {
        endAtSemicolon(static_cast<std::size_t>(p - text), end, blockEnd, next);
        break;
      }
      if (!hasClass(c, kPlainLetter | kMotionLetter) || count == kMostWords) return begin;
      const bool motion = c == 'G';
      unsigned motionCode = 0;  // Word::motionCode: a motion word's, from the G-code table
      // [sign] digits [. digits], at least one digit, fewer than kLargestDigits significant digits
      // before the point (scanNumber's syntax and value); no sign on a code.
      const char* k = p + 1;
      const bool negative = *k == '-';
      if (*k == '+' || *k == '-') {
        if (motion) return begin;
        ++k;
      }
      const char* const first = k;
      while (*k == '0') ++k;
      const char* const significant = k;
      std::uint64_t whole = 0;  // the digits as a whole number (wraps past 19 digits: then not used)
      for (unsigned d; (d = static_cast<unsigned char>(*k) - unsigned{'0'}) <= 9; ++k) whole = whole * 10 + d;
      const auto integerDigits = static_cast<std::size_t>(k - significant);
      bool anyDigit = k > first;
      const bool point = *k == '.';
      std::size_t fractionDigits = 0;
      if (point) {
        const char* const fraction = ++k;
        for (unsigned d; (d = static_cast<unsigned char>(*k) - unsigned{'0'}) <= 9; ++k) whole = whole * 10 + d;
        fractionDigits = static_cast<std::size_t>(k - fraction);
        anyDigit = anyDigit || k > fraction;
      }
      if (!anyDigit || integerDigits >= kLargestDigits) return begin;
      if (!hasClass(*k, kEndsPlainNumber)) return begin;  // what follows makes it no number, or is no plain word
      if (motion) {
        // A code of the motion group written as digits, without a point; a second after a
        // coordinate opens an upper side (noteForSides).
        const GCodeInfo* const code = point ? nullptr : findWholeMotionCode(whole);
        if (!code || (sawCoordinate && sawMotion)) return begin;
        motionCode = motionCodeBits(code);
        sawMotion = true;
      } else {
        const std::uint32_t bit = 1u << (c - 'A');
        if (letters & bit) return begin;  // a repeated word: the word loop reports it
        letters |= bit;
      }
      assert(k - p <= static_cast<std::ptrdiff_t>(Block::kMaxLength));  // parseProgram reads no longer line
      Word& w = words[count++];
      w = Word{.letter = c,
               .hasPoint = point,
               .motionCode = static_cast<std::uint8_t>(motionCode & 7U),
               .length = static_cast<std::uint16_t>(k - p),
               .offset = static_cast<std::uint32_t>(p - text),
               .value = decimalValue(whole, integerDigits, fractionDigits, negative, first, k)};
      if (!motion && c != 'F') {  // a length letter (isLengthLetter)
        sawCoordinate = true;
        evidence.add(w);
      }
      p = k;
    }
    if (count == 0) return begin;
    keepPlainBlock(begin, blockEnd, count, evidence);
    return next;
  }

  /// The integer-unit evidence of a plain block's length words (Program::anyDecimalPoint,
  /// integerLengthWords, largestInteger), gathered as they are read and kept only with the block.
  struct UnitEvidence {
    bool anyPoint = false;
    std::uint32_t integers = 0;
    const Word* largest = nullptr;  // the block's largest integer length word, if any
    void add(const Word& w) {
      if (w.hasPoint) {
        anyPoint = true;
      } else {
        ++integers;
        if (!largest || std::abs(w.value) > std::abs(largest->value)) largest = &w;
      }
    }
  };

  /// The evidence into the program's.
  void keep(const UnitEvidence& evidence) {
    program_.anyDecimalPoint = program_.anyDecimalPoint || evidence.anyPoint;
    program_.integerLengthWords += evidence.integers;
    if (evidence.largest && std::abs(evidence.largest->value) > program_.largestInteger) {
      program_.largestInteger = std::abs(evidence.largest->value);
      program_.largestIntegerWord = *evidence.largest;
    }
  }

  /// tryPlainBlock's block, its `count` words written at Program::plainWords' room: kept, with its
  /// evidence; its text from begin to blockEnd less the blanks before blockEnd.
  void keepPlainBlock(std::size_t begin, std::size_t blockEnd, std::uint16_t count, const UnitEvidence& evidence) {
    keep(evidence);
    Block block;
    block.firstWord = program_.plainWords.at();
    program_.plainWords.keep(count);
    block.offset = static_cast<std::uint32_t>(begin);
    std::size_t last = blockEnd;
    while (last > begin && isBlank(text_[last - 1])) --last;
    block.length = static_cast<std::uint16_t>(last - begin);
    block.wordCount = block.upperFrom = count;
    block.plain = true;
    program_.blocks.push_back(block);
  }

  /// What stands at text_[i] where a word's letter belongs: reported (K0106).
  void strayCharacter(Block& block, std::size_t i, std::size_t end) {
    const char c = text_[i];
    if (c == ')') {
      error(block, Code::UnexpectedCharacter, i, 1, "')' without an opening '('");
    } else if (isDigit(c) || c == '.' || c == '-' || c == '+') {
      const NumberScan n = scanNumber(text_, i, end);
      const std::size_t len = std::max<std::size_t>(1, n.end - i);
      error(block, Code::UnexpectedCharacter, i, len, "number without a letter: every value needs an address letter",
            "write it as a word, e.g. X" + std::string(text_.substr(i, len)));
    } else {
      error(block, Code::UnexpectedCharacter, i, 1, "unexpected " + describeChar(c) + " in a block");
    }
  }

  /// Trims the block's text span, counts its words and keeps it when it has content.
  void finish(Block& block, std::size_t blockEnd) {
    std::size_t last = blockEnd;
    while (last > block.offset && isBlank(text_[last - 1])) --last;
    block.length = static_cast<std::uint16_t>(last - block.offset);
    // Both fit 16 bits: parseProgram reads no line longer than Block::kMaxLength.
    block.wordCount = static_cast<std::uint16_t>(program_.words.size() - block.firstWord);
    if (block.kind == BlockKind::Words && block.upperFrom == 0 && block.wordCount > 0 && !hasUpper_)
      block.upperFrom = block.wordCount;
    hasUpper_ = false;
    block.plain = block.kind == BlockKind::Words && block.wordCount > 0 && plainWords_ && !block.hasError &&
                  !block.colon && !block.twoMotions && !block.lowerCase && !block.unusualValues &&
                  block.upperFrom == block.wordCount;
    plainWords_ = true;
    if (block.plain) {  // its words go where the short road keeps a plain block's
      Word* const kept = program_.plainWords.room(block.wordCount);
      std::copy_n(program_.words.begin() + block.firstWord, block.wordCount, kept);
      program_.words.resize(block.firstWord);
      block.firstWord = program_.plainWords.at();
      program_.plainWords.keep(block.wordCount);
    }
    if (block.wordCount > 0 || block.hasError || block.kind != BlockKind::Words) {
      if (!block.plain) program_.notPlain.push_back(static_cast<std::uint32_t>(program_.blocks.size()));
      program_.blocks.push_back(block);
    }
  }

  /// A ';' at i ends the block; the rest of the line is a comment, or the next block where the
  /// profile's ';' ends blocks (then `next` is after it).
  void endAtSemicolon(std::size_t i, std::size_t end, std::size_t& blockEnd, std::size_t& next) const {
    blockEnd = i;
    if (options_.semicolonEndsBlock && startsBlock(i + 1, end)) next = i + 1;
  }

  /// Does a block start after a ';' that ends blocks? Only words, a comment or '/' do; other text
  /// after ';' (`; a remark`) stays a comment, as on controls where ';' starts one.
  bool startsBlock(std::size_t i, std::size_t end) const {
    while (i < end && isBlank(text_[i])) ++i;
    if (i >= end) return false;
    if (text_[i] == '(' || text_[i] == '/' || text_[i] == '#') return true;
    if (!isLetter(text_[i])) return false;
    std::size_t k = i + 1;
    while (k < end && isBlank(text_[k])) ++k;  // "X 10." is a word
    return k < end && (isDigit(text_[k]) || text_[k] == '-' || text_[k] == '+' || text_[k] == '.');
  }

  /// Where the block that runs from `from` ends: a ';' (then `next` is after it when ';' ends
  /// blocks, else the end of the line) or the end of the line.
  std::size_t findBlockEnd(std::size_t from, std::size_t end, std::size_t& next) const {
    for (std::size_t k = from; k < end; ++k) {
      if (text_[k] == '(') {
        const std::size_t close = text_.find(')', k);
        if (close == std::string_view::npos || close >= end) break;
        k = close;
        continue;
      }
      if (text_[k] == ';') {
        next = options_.semicolonEndsBlock && startsBlock(k + 1, end) ? k + 1 : end;
        return k;
      }
    }
    next = end;
    return end;
  }

  /// Fanuc macro B: `#100 = ...`, `WHILE[...]DO1`, `END1`, `IF[...]GOTO10`, `GOTO10`, `DO1`.
  bool isMacroStatement(std::size_t i, std::size_t end) const {
    // One keyword at most starts with the block's first letter: the common block (G, M, N, X ...)
    // is out after one comparison, a G block after one more.
    auto numbered = [&](std::string_view kw) {  // END1, DO1
      return startsWithKeyword(text_, i, end, kw) && i + kw.size() < end && isDigit(text_[i + kw.size()]);
    };
    switch (upper(text_[i])) {
      case '#': return true;
      case 'W': return startsWithKeyword(text_, i, end, "WHILE");
      case 'G': return i + 1 < end && upper(text_[i + 1]) == 'O' && startsWithKeyword(text_, i, end, "GOTO");
      case 'E': return numbered("END");
      case 'D': return numbered("DO");
      case 'I': {
        if (!startsWithKeyword(text_, i, end, "IF")) return false;
        std::size_t k = i + 2;
        while (k < end && isBlank(text_[k])) ++k;
        return k < end && text_[k] == '[';
      }
      default: return false;
    }
  }

  void noteMacroStatement(std::size_t begin, std::size_t blockEnd, std::uint32_t line) {
    if (macros_.count++ == 0) {
      std::size_t last = blockEnd;
      while (last > begin && isBlank(text_[last - 1])) --last;
      macros_.first = {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(last - begin)};
      macros_.firstLine = line;
    }
    macros_.lastLine = line;
  }

  /// A Sodick macro call: Q, a name of letters and digits, '(' arguments ')', and an optional L
  /// repeat (`QAIC(2,1,0.1250);`, `Q99()LH114;`). Returns its end, or i when there is none.
  std::size_t scanMacroCall(std::size_t i, std::size_t end) const {
    if (upper(text_[i]) != 'Q') return i;
    std::size_t k = i + 1;
    while (k < end && (isLetter(text_[k]) || isDigit(text_[k]))) ++k;
    if (k >= end || text_[k] != '(') return i;
    const std::size_t close = text_.find(')', k);
    if (close == std::string_view::npos || close >= end) return i;
    k = close + 1;
    while (k < end && isBlank(text_[k])) ++k;
    if (k < end && upper(text_[k]) == 'L') {
      ++k;
      std::size_t r = scanRegisterExpression(text_, k, end);
      if (r == k) r = scanNumber(text_, k, end).end;
      k = r;
    }
    return k;
  }

  /// LinuxCNC's `(AXIS,XY_Z_POS,z)` and `(AXIS,UV_Z_POS,z)`: the heights of the two planes.
  void readHeightComment(std::size_t open, std::size_t close, std::uint32_t line) {
    std::string inner;
    for (std::size_t k = open + 1; k < close; ++k)
      if (!isBlank(text_[k])) inner += upper(text_[k]);
    HeightWord h;
    if (inner.starts_with("AXIS,XY_Z_POS,"))
      h.kind = HeightWord::Kind::LinuxCncXyPlane;
    else if (inner.starts_with("AXIS,UV_Z_POS,"))
      h.kind = HeightWord::Kind::LinuxCncUvPlane;
    else
      return;
    const std::string number = inner.substr(14);
    const NumberScan n = scanNumber(number, 0, number.size());
    h.span = {static_cast<std::uint32_t>(open), static_cast<std::uint32_t>(close + 1 - open)};
    h.line = line;
    if (n.status != NumberScan::Ok || n.end != number.size()) {
      diags_.error(Code::ExpectedNumber, &src_, h.span, "the height in this AXIS comment is not a number");
      return;
    }
    h.value = n.value;
    program_.heights.push_back(h);
  }

  /// Sodick `TP<z>` (program plane) and `TN<z>` (lower plane).
  bool tryHeightWord(std::size_t start, std::size_t i, std::size_t end, std::size_t& next) {
    if (i >= end || (upper(text_[i]) != 'P' && upper(text_[i]) != 'N')) return false;
    const NumberScan n = scanNumber(text_, i + 1, end);
    if (n.status != NumberScan::Ok) return false;
    HeightWord h;
    h.kind = upper(text_[i]) == 'P' ? HeightWord::Kind::SodickProgramPlane : HeightWord::Kind::SodickLowerPlane;
    h.value = n.value;
    h.hasPoint = n.hasPoint;
    h.span = {static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(n.end - start)};
    h.line = src_.lineOf(static_cast<std::uint32_t>(start));
    program_.heights.push_back(h);
    next = n.end;
    return true;
  }

  void error(Block& block, Code code, std::size_t at, std::size_t length, std::string message, std::string help = {}) {
    block.hasError = true;
    diags_.error(code, &src_, {static_cast<std::uint32_t>(at), static_cast<std::uint32_t>(length)}, std::move(message),
                 std::move(help));
  }

  /// `H001 = +0.13`, `C000 = ...`, `E001= ...`: letter, digits, blanks, '='.
  bool trySetting(std::size_t i, std::size_t end, std::uint32_t line) {
    const std::size_t start = i;
    if (!isLetter(text_[i])) return false;
    ++i;
    std::size_t digitsFrom = i;
    while (i < end && isDigit(text_[i])) ++i;
    if (i == digitsFrom) return false;
    const std::size_t nameEnd = i;
    while (i < end && isBlank(text_[i])) ++i;
    if (i >= end || text_[i] != '=') return false;
    ++i;
    std::size_t valueEnd = text_.find(';', i);
    if (valueEnd == std::string_view::npos || valueEnd > end) valueEnd = end;
    std::size_t vb = i, ve = valueEnd;
    while (vb < ve && isBlank(text_[vb])) ++vb;
    while (ve > vb && isBlank(text_[ve - 1])) --ve;
    Setting s;
    s.name = std::string(1, upper(text_[start])) + std::string(text_.substr(start + 1, nameEnd - start - 1));
    s.value = std::string(text_.substr(vb, ve - vb));
    s.span = {static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(ve - start)};
    s.line = line;
    if (s.value.empty()) {
      diags_.error(Code::MalformedSetting, &src_,
                   {static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(i - start)},
                   "setting " + s.name + " has no value after '='");
      return true;
    }
    program_.settings.push_back(std::move(s));
    return true;
  }

  /// Appends a word of the block being read to the program, keeping the integer-unit evidence.
  void push(Block& block, std::size_t start, std::size_t stop, char letter, WordValue kind, double value,
            bool hasPoint) {
    upperLetters_ |= letter == 'U' || letter == 'V' || letter == 'K' || letter == 'L';
    plainWords_ = plainWords_ && isPlainWord(letter, kind, value);
    block.unusualValues |= kind != WordValue::Number;
    Word w;
    w.letter = letter;
    w.kind = kind;
    w.hasPoint = hasPoint;
    w.offset = static_cast<std::uint32_t>(start);
    w.length = static_cast<std::uint16_t>(std::min<std::size_t>(stop - start, 0xFFFF));
    w.value = value;
    // A G word written as digits that names a motion code carries it, as the plain pass's do.
    if (letter == 'G' && kind == WordValue::Number && !hasPoint && value >= 0 && value < 1e6)
      if (static_cast<double>(static_cast<std::uint64_t>(value)) == value)
        w.motionCode =
            static_cast<std::uint8_t>(motionCodeBits(findWholeMotionCode(static_cast<std::uint64_t>(value))) & 7U);
    if (isLengthLetter(letter) && kind == WordValue::Number) {
      UnitEvidence evidence;
      evidence.add(w);
      keep(evidence);
    }
    program_.words.push_back(w);
  }

  /// How many words the block being read has so far.
  [[nodiscard]] int wordsSoFar(const Block& block) const {
    return static_cast<int>(program_.words.size() - block.firstWord);
  }

  /// One word from text_[i] (its letter) to at most `end`: pushed, or reported; the index after it.
  std::size_t parseWord(Block& block, std::size_t i, std::size_t end) {
    const std::size_t start = i;
    char letter = upper(text_[i]);
    if (letter == 'Z' && options_.upperAxesUZ) letter = 'V';
    ++i;
    while (i < end && isBlank(text_[i])) ++i;  // "X 10." is accepted
    // B is no wire word (3B code starts with it), except a rotary axis homed with G28/G30 (`G28 B`).
    if (!isWordLetter(letter) && !(letter == 'B' && homing_)) return unknownLetter(block, start, i, end, letter);
    if (std::size_t next = 0; letter == 'T' && tryHeightWord(start, i, end, next)) return next;
    if (const std::size_t next = valueAtMachine(block, start, i, end, letter); next != i) return next;
    const NumberScan n = scanNumber(text_, i, end);
    if (n.status == NumberScan::Missing) return noNumber(block, start, i, end, letter);
    const std::size_t stop = n.end;
    if (n.status == NumberScan::TooManyDigits) {
      error(block, Code::NumberOutOfRange, start, stop - start, "number has more than 18 digits");
      return stop;
    }
    if (const std::size_t next = malformedEnd(block, start, n, end, letter); next != stop) return next;
    if (n.integerDigits >= kLargestDigits) {
      error(block, Code::NumberOutOfRange, start, stop - start, "number is out of range (limit 1e9)");
      return stop;
    }
    noteForSides(block, letter, n.value);
    push(block, start, stop, letter, WordValue::Number, n.value, n.hasPoint);
    return stop;
  }

  /// Fanuc's optional corner word at text_[i] (the comma): `,R r` or `,C c`, read as the word R or C
  /// marked Word::corner, its span from the comma. The block keeps its words (never plain). The
  /// index after it.
  std::size_t parseCornerWord(Block& block, std::size_t i, std::size_t end) {
    plainWords_ = false;
    const std::size_t before = program_.words.size();
    const std::size_t next = parseWord(block, i + 1, end);
    if (program_.words.size() == before + 1) {
      Word& w = program_.words.back();
      w.corner = true;
      w.offset = static_cast<std::uint32_t>(i);
      w.length = static_cast<std::uint16_t>(std::min<std::size_t>(next - i, 0xFFFF));
    }
    return next;
  }

  /// A letter that is no word: one diagnostic for it and the number after it.
  std::size_t unknownLetter(Block& block, std::size_t start, std::size_t i, std::size_t end, char letter) {
    // Skip the number that follows, if any, so one bad word is one diagnostic.
    const NumberScan n = scanNumber(text_, i, end);
    const std::size_t stop = n.status == NumberScan::Missing ? start + 1 : n.end;
    // A B after other words of a block moves a rotary axis; a B that starts one is likely 3B code.
    const bool axisMove = letter == 'B' && wordsSoFar(block) > 0;
    error(block, Code::UnknownWord, start, stop - start,
          axisMove ? std::string("'B' turns a rotary axis while the wire moves: Kerf does not model it, so this move "
                                 "cannot be checked")
                   : std::string("unknown word letter '") + letter + "'",
          axisMove        ? "a B that only homes the axis (G28 B) is read as a note"
          : letter == 'B' ? "this looks like 3B code (B x B y B J G Z), not ISO G-code"
                          : std::string{});
    return std::max(stop, start + 1);
  }

  /// A value known only at the machine (a register H.., a macro value # or [..]) at i: pushed;
  /// the index after it, or i when there is none.
  std::size_t valueAtMachine(Block& block, std::size_t start, std::size_t i, std::size_t end, char letter) {
    const char lead = i < end && (text_[i] == '+' || text_[i] == '-') && i + 1 < end ? text_[i + 1]
                      : i < end                                                      ? text_[i]
                                                                                     : 0;
    if (lead == 'H' || lead == 'h') {
      if (const std::size_t r = scanRegisterExpression(text_, i, end); r != i) {
        push(block, start, r, letter, WordValue::Register, 0.0, false);
        return r;
      }
    } else if (lead == '#' || lead == '[') {
      if (const std::size_t m = scanMacroValue(text_, i, end); m != i) {
        push(block, start, m, letter, WordValue::Macro, 0.0, false);
        return m;
      }
    }
    return i;
  }

  /// No number after the letter: a direction (`Y+`), a bare axis after G28/G30, or an error with
  /// a hint at what was meant.
  std::size_t noNumber(Block& block, std::size_t start, std::size_t i, std::size_t end, char letter) {
    // `Y+` / `X-`: a direction (edge sensing); an axis alone after G28/G30: home it.
    if (i < end && (text_[i] == '+' || text_[i] == '-') && (i + 1 >= end || !isDigit(text_[i + 1]))) {
      push(block, start, i + 1, letter, WordValue::Direction, text_[i] == '-' ? -1.0 : 1.0, false);
      return i + 1;
    }
    if (homing_ && isAxisLetter(letter)) {
      push(block, start, start + 1, letter, WordValue::Bare, 0.0, false);
      return start + 1;
    }
    std::string read = i < end ? describeChar(text_[i]) : std::string("the end of the line");
    std::string help;
    if (i < end && (text_[i] == 'O' || text_[i] == 'o') && (letter == 'G' || letter == 'M'))
      help = std::string("did you mean ") + letter + "0" + std::string(text_.substr(i + 1, 1)) +
             "? (the digit zero, not the letter O)";
    else if ((text_[start] == 'l' || text_[start] == 'I' || text_[start] == 'O' || text_[start] == 'o') && start > 0 &&
             isDigit(text_[start - 1]))
      help = std::string("did you mean the digit ") + (text_[start] == 'l' || text_[start] == 'I' ? "1" : "0") +
             " instead of the letter '" + text_[start] + "'?";
    else if (i + 2 < end && upper(text_[i]) == 'N' && upper(text_[i + 1]) == 'A' && upper(text_[i + 2]) == 'N')
      help = "NaN is not a number an NC control accepts";
    error(block, Code::ExpectedNumber, start, 1, std::string("expected a number after '") + letter + "', read " + read,
          help);
    return start + 1;
  }

  /// What follows a number that makes it no number: a second point, a decimal comma, an exponent,
  /// a sign inside. Reported; the index after the malformed text, or n.end when it is well formed.
  std::size_t malformedEnd(Block& block, std::size_t start, const NumberScan& n, std::size_t end, char letter) {
    const std::size_t stop = n.end;
    if (stop < end && text_[stop] == '.') {
      std::size_t j = stop;
      while (j < end && (isDigit(text_[j]) || text_[j] == '.')) ++j;
      error(block, Code::MalformedNumber, start, j - start, "number has a second decimal point");
      return j;
    }
    if (stop + 1 < end && text_[stop] == ',' && isDigit(text_[stop + 1]) && !n.hasPoint) {
      std::size_t j = stop + 1;
      while (j < end && isDigit(text_[j])) ++j;
      const std::string written(text_.substr(start, j - start));
      std::string meant = written;
      meant[stop - start] = '.';
      meant[0] = letter;
      error(block, Code::DecimalComma, start, j - start,
            "'" + written + "' has a comma where a decimal point belongs: NC numbers take a point",
            "did you mean " + meant + "?");
      return j;
    }
    if (stop < end && (text_[stop] == 'e' || text_[stop] == 'E')) {
      std::size_t j = stop + 1;
      if (j < end && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j < end && isDigit(text_[j])) {
        while (j < end && isDigit(text_[j])) ++j;
        error(block, Code::ExponentNotation, start, j - start, "exponent notation is not allowed in NC words",
              "write the number out in full with a decimal point");
        return j;
      }
    }
    if (stop < end && (text_[stop] == '+' || text_[stop] == '-') && stop + 1 < end && isDigit(text_[stop + 1])) {
      error(block, Code::MalformedNumber, start, stop + 1 - start, "sign inside a number");
      NumberScan rest = scanNumber(text_, stop + 1, end);
      return rest.end;
    }
    return stop;
  }

  /// A second motion word after a coordinate opens the upper side (`G2 X Y I J G1 U V`, cnc3); a
  /// single motion word may stand anywhere (`X10 Y5 G1`). G28/G30 let axes stand bare after them.
  void noteForSides(const Block& block, char letter, double value) {
    const bool motionG = letter == 'G' && isMotionCode(value);
    if (splitAt_ < 0 && motionG && sawCoordinate_ && sawMotion_) splitAt_ = wordsSoFar(block);
    sawMotion_ |= motionG;
    if (letter == 'X' || letter == 'Y' || letter == 'I' || letter == 'J' || letter == 'R' || letter == 'U' ||
        letter == 'V')
      sawCoordinate_ = true;
    if (letter == 'G' && isHomingCode(value)) homing_ = true;
  }

  // ---- 4. the sides of a 4-axis block ----------------------------------------------------------

  /// Orders the block's words lower side first and reports a letter written twice on one side.
  /// Positional sides after ':' or a second motion word; otherwise by letter.
  void assignSides(Block& block) {
    Word* words = program_.words.data() + block.firstWord;
    const std::size_t n = program_.words.size() - block.firstWord;
    std::vector<std::uint8_t>& side = sides_;  // 0 lower, 1 upper (kept between blocks: no allocation)
    side.assign(n, 0);
    if (splitAt_ >= 0) {
      for (std::size_t k = static_cast<std::size_t>(splitAt_); k < n; ++k) side[k] = 1;
      block.colon = colon_;
      block.twoMotions = !colon_;
    } else if (upperLetters_) {
      std::uint32_t seenLower = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const char c = words[k].letter;
        const std::uint32_t bit = 1u << (c - 'A');
        if (words[k].corner) continue;  // a corner word belongs to the block's end, on the lower side
        if (c == 'U' || c == 'V' || c == 'K' || c == 'L') {
          side[k] = 1;
        } else if ((c == 'I' || c == 'J' || c == 'R') && (seenLower & bit)) {
          side[k] = 1;  // a second centre for the upper arc: `G2 X Y I J U V I J`
        } else {
          seenLower |= bit;
        }
      }
    }
    // A letter twice on one side (G and M may repeat).
    std::uint32_t seen[2] = {0, 0};
    std::uint32_t placed = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Word& w = words[k];
      // A corner word has bits of its own (26 for ,R, 27 for ,C): `R5. ,R2.` is no repeat.
      const std::uint32_t bit = w.corner ? (1u << 26) << (w.letter == 'C') : 1u << (w.letter - 'A');
      if ((seen[side[k]] & bit) && w.letter != 'G' && w.letter != 'M') {
        error(block, Code::RepeatedWord, w.offset, w.length,
              std::string("word '") + (w.corner ? "," : "") + w.letter + "' appears twice in one block");
        return;
      }
      seen[side[k]] |= bit;
      placed += side[k] == 0;
    }
    block.upperFrom = static_cast<std::uint16_t>(placed);  // at most the block's words
    hasUpper_ = true;
    if (splitAt_ >= 0 || !upperLetters_) return;  // already in order
    // By letter: the lower side first, each side in the order written.
    scratch_.assign(words, words + n);
    std::size_t at = 0;
    for (int s = 0; s < 2; ++s)
      for (std::size_t k = 0; k < n; ++k)
        if (side[k] == s) words[at++] = scratch_[k];
  }

  const SourceFile& src_;
  std::string_view text_;
  Program& program_;
  Diagnostics& diags_;
  const ParseOptions& options_;
  std::vector<std::uint8_t> sides_;  ///< assignSides' side of each of the block's words
  std::vector<Word> scratch_;        ///< assignSides' copy of a block it reorders
  bool upperLetters_ = false;        ///< U V K L among the block's words
  bool plainWords_ = true;           ///< every word of the block so far is plain (Block::plain)
  int splitAt_ = -1;                 ///< index in the block's words where a positional upper side starts
  bool colon_ = false;               ///< that split was a ':'
  bool sawCoordinate_ = false;       ///< X Y I J R U V seen in this block
  bool sawMotion_ = false;           ///< a motion word (G00-G03) seen in this block
  bool homing_ = false;              ///< G28 or G30 seen in this block: bare axis letters allowed
  bool hasUpper_ = false;            ///< assignSides set upperFrom for this block
  MacroTally macros_;
};

}  // namespace line_parser

using line_parser::LineParser;
using line_parser::MacroTally;

// ---- 5. plain blocks' words ----------------------------------------------------------------

Word* PlainWords::roomInAnotherChunk(std::size_t n) {
  std::size_t chunk = size_ / kChunkWords;
  while (size_ % kChunkWords + n > capacityOf(chunk)) {  // a block's words lie in one chunk
    ++chunk;
    if (chunk >= std::numeric_limits<std::uint32_t>::max() / kChunkWords)
      throw std::length_error("parseProgram: more than 2^32 words");
    size_ = static_cast<std::uint32_t>(chunk * kChunkWords);
  }
  if (chunks_.size() <= chunk) chunks_.resize(chunk + 1);
  if (!chunks_[chunk]) chunks_[chunk].reset(static_cast<Word*>(::operator new(capacityOf(chunk) * sizeof(Word))));
  return chunks_[chunk].get() + size_ % kChunkWords;
}

void PlainWords::clear() {
  chunks_.resize(std::min<std::size_t>(chunks_.size(), 1));
  givenBack_ = 0;
  size_ = 0;
}

struct WordReader::Again {
  explicit Again(const SourceFile& source) : parser(source, program, diags, options) { program.source = &source; }
  Program program;
  Diagnostics diags;
  const ParseOptions options;
  LineParser parser;
};

WordReader::WordReader(const Program& program) : program_(program) {}
WordReader::~WordReader() = default;

std::span<const Word> WordReader::parseAgain(const Block& b) {
  // Given back: the block's text parsed again, alone, by the parser. Its span ends where a ';', a
  // blank or the line's end follows, none of a number's characters (LineParser::parseLine); a
  // plain block has no Z (ParseOptions::upperAxesUZ) and no ';' (semicolonEndsBlock) inside it,
  // so the default options read it as its first parse did.
  if (!again_) again_ = std::make_unique<Again>(*program_.source);
  Program& again = again_->program;
  again.blocks.clear();
  again.words.clear();
  again.notPlain.clear();
  again.plainWords.clear();
  again_->parser.parseLine(b.offset, std::size_t{b.offset} + b.length, program_.source->lineOf(b.offset));
  buffer_.clear();
  if (!again.blocks.empty()) {
    const Block& read = again.blocks.front();
    const std::span<const Word> words =
        read.plain ? std::span<const Word>(again.plainWords.find(read.firstWord), read.wordCount) : again.wordsOf(read);
    buffer_.assign(words.begin(), words.end());
  }
  return buffer_;
}

// ---- 6. the whole text ------------------------------------------------------------------------

namespace {

/// The macro B statements of the file: one diagnostic at the first, naming how many there are.
void reportMacroStatements(const MacroTally& macros, const SourceFile& src, Diagnostics& diags) {
  if (macros.count == 0) return;
  std::string where;
  if (macros.count > 1)
    where = " (" + std::to_string(macros.count) + " macro lines, on lines " + std::to_string(macros.firstLine) +
            " to " + std::to_string(macros.lastLine) + ")";
  diags.error(Code::MacroStatement, &src, macros.first,
              "macro B statement: variables, loops and jumps (#, WHILE, IF, GOTO) are evaluated by the control, "
              "and Kerf does not run them" +
                  where,
              "the blocks around them are read once, in order, as if the macro lines were absent; a value "
              "written as #n is known only at the machine");
}

}  // namespace

Program parseProgram(const SourceFile& source, Diagnostics& diags, const ParseOptions& options) {
  Program program;
  program.source = &source;
  const std::string_view text = source.text();
  // A NUL byte near the start means a binary file, not NC text: one diagnostic, not thousands.
  if (const std::size_t nul = text.substr(0, 4096).find('\0'); nul != std::string_view::npos) {
    diags.error(Code::UnexpectedCharacter, &source, {static_cast<std::uint32_t>(nul), 1},
                "the file contains NUL bytes: it is not an NC text file");
    return program;
  }
  // Room for what a typical wire program holds: a block of about 24 bytes. The words vector holds
  // only the blocks that are not plain, and grows as they come.
  program.blocks.reserve(text.size() / 24);
  // A UTF-8 byte-order mark (some Windows editors write one) is not part of the program.
  const std::size_t bom = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  LineParser parser(source, program, diags, options);
  for (std::uint32_t line = 1; line <= source.lineCount(); ++line) {
    auto [begin, end] = source.lineRange(line);
    if (line == 1) begin = static_cast<std::uint32_t>(std::min<std::size_t>(bom, end));
    // A '%' line opens the program; a '%' line after content (a block or a setting read: both
    // lists only grow) closes it, and the rest is ignored.
    std::size_t at = begin;
    while (at < end && isBlank(text[at])) ++at;
    if (at < end && text[at] == '%') {
      if (!program.blocks.empty() || !program.settings.empty()) break;
      continue;
    }
    if (end - begin > Block::kMaxLength) {
      diags.error(Code::BlockTooLong, &source, {static_cast<std::uint32_t>(begin + Block::kMaxLength), 1},
                  "a line of more than " + std::to_string(Block::kMaxLength) + " characters: it is not read",
                  "split the line into blocks");
      continue;
    }
    parser.parseLine(begin, end, line);
  }
  reportMacroStatements(parser.macros(), source, diags);
  return program;
}

}  // namespace kerf::converter
