// ISO block parser.
//
// Sections: 1. character classes and number scanning
//           2. one line: settings, comments, words
//           3. the whole text: '%' frame, blocks
#include "kerf/converter/program.h"

#include <array>
#include <cmath>
#include <string>

namespace kerf::converter {
namespace {

// ---- 1. characters and numbers --------------------------------------------------------------

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Letters that are words in ISO wire programs. B and W are not (B belongs to 3B code).
bool isWordLetter(char u) { return u != 'B' && u != 'W'; }

/// Letters whose numbers are lengths: they decide --integer-unit heuristics.
bool isLengthLetter(char u) { return u == 'X' || u == 'Y' || u == 'U' || u == 'V' || u == 'I' || u == 'J' || u == 'R'; }

constexpr std::array<double, 19> kPowersOfTen = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8, 1e9,
                                                 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};

/// Numbers larger than this are refused (K0105): no wire machine travels a kilometre.
constexpr double kLargestNumber = 1e9;
/// At most this many digits in one number.
constexpr int kMaxDigits = 18;

struct NumberScan {
  enum Status { Ok, Missing, TooManyDigits } status = Missing;
  bool hasPoint = false;
  std::size_t end = 0;  ///< one past the last character used
  double value = 0.0;
};

/// [sign] digits [. digits] — no exponent, no spaces inside. The value is mantissa / 10^k with
/// both exact doubles, so it is correctly rounded (the same as strtod) for up to 15 digits.
NumberScan scanNumber(std::string_view text, std::size_t pos) {
  NumberScan s;
  std::size_t i = pos;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  std::uint64_t mantissa = 0;
  int digits = 0, fraction = 0;
  bool anyDigit = false;
  auto takeDigits = [&](bool afterPoint) {
    while (i < text.size() && isDigit(text[i])) {
      anyDigit = true;
      if (mantissa == 0 && text[i] == '0') {  // leading zeros do not count as digits
        if (afterPoint) ++fraction;
        ++i;
        continue;
      }
      if (digits < kMaxDigits) {
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
        ++digits;
        if (afterPoint) ++fraction;
      } else if (!afterPoint) {
        s.status = NumberScan::TooManyDigits;
      }  // further fraction digits beyond 18 significant ones are dropped
      ++i;
    }
  };
  takeDigits(false);
  if (i < text.size() && text[i] == '.') {
    s.hasPoint = true;
    ++i;
    takeDigits(true);
  }
  s.end = i;
  if (!anyDigit) {
    s.status = NumberScan::Missing;
    return s;
  }
  if (s.status == NumberScan::TooManyDigits) return s;
  s.status = NumberScan::Ok;
  double v = static_cast<double>(mantissa);
  if (fraction > 0) v = fraction < static_cast<int>(kPowersOfTen.size()) ? v / kPowersOfTen[fraction] : 0.0;
  s.value = negative ? -v : v;
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

// ---- 2. one line ------------------------------------------------------------------------------

class LineParser {
 public:
  LineParser(const SourceFile& src, Program& program, Diagnostics& diags)
      : src_(src), text_(src.text()), program_(program), diags_(diags) {}

  /// Parses [begin, end) — one line without its line break.
  void parseLine(std::size_t begin, std::size_t end, std::uint32_t line) {
    std::size_t i = begin;
    while (i < end && isBlank(text_[i])) ++i;
    if (i >= end) return;
    if (trySetting(i, end, line)) return;

    Block block;
    block.firstWord = static_cast<std::uint32_t>(program_.words.size());
    block.offset = static_cast<std::uint32_t>(i);
    block.line = line;
    std::size_t blockEnd = end;
    if (text_[i] == '/') {
      block.blockDelete = true;
      ++i;
    }
    std::uint32_t seen = 0;  // letters already on this side of the block (bit per letter)
    upperStarted_ = false;
    sawCoordinate_ = false;
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
          blockEnd = end;
          break;
        }
        if (close == std::string_view::npos || close >= end) {
          error(block, Code::UnterminatedComment, i, 1, "comment is not closed on its line",
                "add ')' — a comment cannot span lines");
          blockEnd = end;
          break;
        }
        readHeightComment(i, close, line);
        i = close + 1;
        continue;
      }
      if (c == ';') {  // end of block; the rest of the line is a comment
        blockEnd = i;
        break;
      }
      if (c == ':') {  // Sodick: the lower contour before, the upper after (FORMATS.md §2)
        if (upperStarted_) {
          error(block, Code::UnexpectedCharacter, i, 1,
                block.colon ? "a second ':' in one block" : "':' after the upper contour's words have begun");
          blockEnd = end;
          break;
        }
        startUpper(block, seen);
        block.colon = true;
        ++i;
        continue;
      }
      if (!isLetter(c)) {
        if (c == ')') {
          error(block, Code::UnexpectedCharacter, i, 1, "')' without an opening '('");
        } else if (isDigit(c) || c == '.' || c == '-' || c == '+') {
          const NumberScan n = scanNumber(text_, i);
          const std::size_t len = std::max<std::size_t>(1, n.end - i);
          error(block, Code::UnexpectedCharacter, i, len,
                "number without a letter: every value needs an address letter",
                "write it as a word, e.g. X" + std::string(text_.substr(i, len)));
          blockEnd = end;
          break;
        } else {
          error(block, Code::UnexpectedCharacter, i, 1, "unexpected " + describeChar(c) + " in a block");
        }
        blockEnd = end;
        break;
      }
      i = parseWord(block, i, end, seen);
      if (block.hasError) {  // one error per block: what follows is likely noise from it
        blockEnd = end;
        break;
      }
    }
    // Trim trailing blanks from the block's text span.
    std::size_t last = blockEnd;
    while (last > block.offset && isBlank(text_[last - 1])) --last;
    block.length = static_cast<std::uint32_t>(last - block.offset);
    block.wordCount = static_cast<std::uint32_t>(program_.words.size()) - block.firstWord;
    if (!upperStarted_) block.upperFrom = block.wordCount;
    if (block.wordCount > 0 || block.hasError) program_.blocks.push_back(block);
  }

 private:
  void startUpper(Block& block, std::uint32_t& seen) {
    upperStarted_ = true;
    block.upperFrom = static_cast<std::uint32_t>(program_.words.size()) - block.firstWord;
    seen = 0;  // the upper side has its own X Y I J R
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
    const NumberScan n = scanNumber(number, 0);
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
  bool tryHeightWord(Block& block, std::size_t start, std::size_t i, std::size_t end, std::size_t& next) {
    if (i >= end || (upper(text_[i]) != 'P' && upper(text_[i]) != 'N')) return false;
    const NumberScan n = scanNumber(text_, i + 1);
    if (n.status != NumberScan::Ok) return false;
    HeightWord h;
    h.kind = upper(text_[i]) == 'P' ? HeightWord::Kind::SodickProgramPlane : HeightWord::Kind::SodickLowerPlane;
    h.value = n.value;
    h.hasPoint = n.hasPoint;
    h.span = {static_cast<std::uint32_t>(start), static_cast<std::uint32_t>(n.end - start)};
    h.line = block.line;
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

  std::size_t parseWord(Block& block, std::size_t i, std::size_t end, std::uint32_t& seen) {
    const std::size_t start = i;
    const char letter = upper(text_[i]);
    ++i;
    while (i < end && isBlank(text_[i])) ++i;  // "X 10." is accepted
    if (!isWordLetter(letter)) {
      // Skip the number that follows, if any, so one bad word is one diagnostic.
      const NumberScan n = scanNumber(text_, i);
      const std::size_t stop = n.status == NumberScan::Missing ? start + 1 : n.end;
      error(block, Code::UnknownWord, start, stop - start, std::string("unknown word letter '") + letter + "'",
            letter == 'B' ? "this looks like 3B code (B x B y B J G Z), not ISO G-code" : std::string{});
      return std::max(stop, start + 1);
    }
    if (std::size_t next = 0; letter == 'T' && tryHeightWord(block, start, i, end, next)) return next;
    const NumberScan n = scanNumber(text_, i);
    if (n.status == NumberScan::Missing) {
      std::string read = i < end ? describeChar(text_[i]) : std::string("the end of the line");
      std::string help;
      if (i < end && (text_[i] == 'O' || text_[i] == 'o') && (letter == 'G' || letter == 'M'))
        help = std::string("did you mean ") + letter + "0" + std::string(text_.substr(i + 1, 1)) +
               "? (the digit zero, not the letter O)";
      else if ((text_[start] == 'l' || text_[start] == 'I' || text_[start] == 'O' || text_[start] == 'o') &&
               start > 0 && isDigit(text_[start - 1]))
        help = std::string("did you mean the digit ") + (text_[start] == 'l' || text_[start] == 'I' ? "1" : "0") +
               " instead of the letter '" + text_[start] + "'?";
      else if (i + 2 < end && upper(text_[i]) == 'N' && upper(text_[i + 1]) == 'A' && upper(text_[i + 2]) == 'N')
        help = "NaN is not a number an NC control accepts";
      error(block, Code::ExpectedNumber, start, 1,
            std::string("expected a number after '") + letter + "', read " + read, help);
      return start + 1;
    }
    std::size_t stop = n.end;
    if (n.status == NumberScan::TooManyDigits) {
      error(block, Code::NumberOutOfRange, start, stop - start, "number has more than 18 digits");
      return stop;
    }
    if (stop < end && text_[stop] == '.') {
      std::size_t j = stop;
      while (j < end && (isDigit(text_[j]) || text_[j] == '.')) ++j;
      error(block, Code::MalformedNumber, start, j - start, "number has a second decimal point");
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
      NumberScan rest = scanNumber(text_, stop + 1);
      return rest.end;
    }
    if (std::abs(n.value) >= kLargestNumber) {
      error(block, Code::NumberOutOfRange, start, stop - start, "number is out of range (limit 1e9)");
      return stop;
    }
    // The upper side of an xyuv-abs block starts at its first U/V word or at a second motion
    // word after a coordinate (`G2 X Y I J G1 U V`); its I J R may repeat the lower side's.
    if (!upperStarted_ &&
        (letter == 'U' || letter == 'V' ||
         (letter == 'G' && sawCoordinate_ && n.value >= 0 && n.value <= 3 && n.value == std::floor(n.value))))
      startUpper(block, seen);
    if (letter == 'X' || letter == 'Y' || letter == 'I' || letter == 'J' || letter == 'R') sawCoordinate_ = true;
    const std::uint32_t bit = 1u << (letter - 'A');
    if ((seen & bit) && letter != 'G' && letter != 'M') {
      error(block, Code::RepeatedWord, start, stop - start,
            std::string("word '") + letter + "' appears twice in one block");
      return stop;
    }
    seen |= bit;
    Word w;
    w.letter = letter;
    w.hasPoint = n.hasPoint;
    w.offset = static_cast<std::uint32_t>(start);
    w.length = static_cast<std::uint16_t>(std::min<std::size_t>(stop - start, 0xFFFF));
    w.value = n.value;
    if (isLengthLetter(letter)) {
      if (n.hasPoint) {
        program_.anyDecimalPoint = true;
      } else if (std::abs(n.value) > program_.largestInteger) {
        program_.largestInteger = std::abs(n.value);
        program_.largestIntegerWord = static_cast<std::uint32_t>(program_.words.size());
      }
    }
    program_.words.push_back(w);
    return stop;
  }

  const SourceFile& src_;
  std::string_view text_;
  Program& program_;
  Diagnostics& diags_;
  bool upperStarted_ = false;   ///< this block's upper side has begun
  bool sawCoordinate_ = false;  ///< X Y I J R seen in this block
};

}  // namespace

// ---- 3. the whole text ------------------------------------------------------------------------

Program parseProgram(const SourceFile& source, Diagnostics& diags) {
  Program program;
  program.source = &source;
  const std::string_view text = source.text();
  program.words.reserve(text.size() / 6);
  program.blocks.reserve(text.size() / 24);
  // A NUL byte near the start means a binary file, not NC text: one diagnostic, not thousands.
  if (const std::size_t nul = text.substr(0, 4096).find('\0'); nul != std::string_view::npos) {
    diags.error(Code::UnexpectedCharacter, &source, {static_cast<std::uint32_t>(nul), 1},
                "the file contains NUL bytes: it is not an NC text file");
    return program;
  }
  LineParser parser(source, program, diags);
  std::size_t pos = 0;
  std::uint32_t line = 1;
  bool sawContent = false;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::size_t end = nl;
    if (end > pos && text[end - 1] == '\r') --end;
    // A '%' line opens the program; a '%' line after content closes it (the rest is ignored).
    std::size_t first = pos;
    while (first < end && isBlank(text[first])) ++first;
    if (first < end && text[first] == '%') {
      if (sawContent) break;
    } else {
      const std::size_t before = program.blocks.size() + program.settings.size();
      parser.parseLine(pos, end, line);
      if (program.blocks.size() + program.settings.size() != before) sawContent = true;
    }
    pos = nl + 1;
    ++line;
  }
  return program;
}

}  // namespace kerf::converter
