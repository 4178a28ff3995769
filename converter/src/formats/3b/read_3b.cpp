// The 3B reader (docs/3b.md; FORMATS §4): records to moves, one Move per record.
#include "kerf/converter/formats/3b/read_3b.h"

#include "kerf/converter/nc/number_format.h"
#include "three_b.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace kerf::converter {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
char upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }

/// Skips blanks and `;` comments from i.
std::size_t skipBlank(std::string_view t, std::size_t i) {
  while (i < t.size()) {
    if (isSpace(t[i])) {
      ++i;
    } else if (t[i] == ';') {
      while (i < t.size() && t[i] != '\n' && t[i] != '\r') ++i;
    } else {
      break;
    }
  }
  return i;
}

}  // namespace

std::string firstThreeBRecord(std::string_view text) {
  const std::size_t i = skipBlank(text, 0);
  if (i >= text.size() || upper(text[i]) != 'B') return {};
  // A B field: B, blanks, digits or the next B.
  std::size_t j = i + 1;
  while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
  if (j < text.size() && !std::isdigit(static_cast<unsigned char>(text[j])) && upper(text[j]) != 'B') return {};
  // A count direction somewhere in the first records.
  const std::size_t window = std::min<std::size_t>(text.size(), i + 4096);
  for (std::size_t k = i; k + 1 < window; ++k) {
    if (upper(text[k]) != 'G') continue;
    std::size_t m = k + 1;
    while (m < window && (text[m] == ' ' || text[m] == '\t')) ++m;
    if (m < window && (upper(text[m]) == 'X' || upper(text[m]) == 'Y')) {
      std::size_t end = i;
      while (end < text.size() && text[end] != '\n' && text[end] != '\r' && end - i < 40) ++end;
      return std::string(text.substr(i, end - i));
    }
  }
  return {};
}

namespace {

using geometry::Vec2;
using three_b::Axis;

struct ParsedRecord {
  std::uint32_t begin = 0, end = 0;        ///< the record's text
  std::array<std::uint64_t, 3> field{};    ///< x, y, J in µm
  std::array<std::uint32_t, 3> fieldAt{};  ///< offset of each B
  Axis axis = Axis::X;
  std::uint32_t axisAt = 0;
  bool arc = false, ccw = false;
  int quadrant = 1;
  std::uint32_t zAt = 0;
};

class ThreeBReader {
 public:
  ThreeBReader(const SourceFile& src, const ThreeBOptions& options, Diagnostics& diags)
      : src_(src), t_(src.text()), diags_(diags), position_(options.start) {
    path_.start = options.start;
    path_.format = InputFormat::ThreeB;
  }

  Toolpath run() {
    std::size_t i = 0;
    std::size_t records = 0;
    for (;;) {
      i = skipBlank(t_, i);
      if (i >= t_.size()) break;
      const char c = upper(t_[i]);
      if ((c == 'D' || c == 'F') && i + 1 < t_.size() && upper(t_[i + 1]) == c) {  // DD, FF: the end
        path_.endedProperly = true;
        const std::size_t after = skipBlank(t_, i + 2);
        if (after < t_.size())
          diags_.warning(Code::WordIgnored, &src_, span(after, after + 1),
                         "text after the end (" + std::string(t_.substr(i, 2)) + ") is not read");
        break;
      }
      if (c == 'D') {  // a single D: the machine stops here (no motion)
        diags_.note(Code::MachineCode, &src_, span(i, i + 1),
                    "D: the machine stops here (a pause, as M00); it moves nothing");
        ++i;
        continue;
      }
      ParsedRecord r;
      std::size_t next = i;
      if (parseRecord(i, r, next)) {
        ++records;
        apply(r);
        i = next;
      } else {
        i = lineEnd(next);  // go on at the next line
      }
    }
    path_.blocks = records;
    if (records == 0 && diags_.errorCount() == 0)
      diags_.error(Code::NothingCut, &src_, SourceSpan{0, 0}, "the file holds no 3B record: nothing to cut");
    else if (!path_.endedProperly && records > 0)
      diags_.note(Code::MissingProgramEnd, &src_, SourceSpan::wholeFile(), "the 3B program has no end (DD)",
                  "most 3B programs end with DD (some controls take FF); the machine stops after the last record");
    return std::move(path_);
  }

 private:
  SourceSpan span(std::size_t a, std::size_t b) const {
    return {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b > a ? b - a : 1)};
  }
  std::size_t lineEnd(std::size_t i) const {
    while (i < t_.size() && t_[i] != '\n' && t_[i] != '\r') ++i;
    return i;
  }
  std::size_t skipInline(std::size_t i) const {
    while (i < t_.size() && (t_[i] == ' ' || t_[i] == '\t')) ++i;
    return i;
  }
  std::string shown(std::size_t i) const {
    if (i >= t_.size()) return "the end of the file";
    if (t_[i] == '\n' || t_[i] == '\r') return "the end of the line";
    return "'" + std::string(1, t_[i]) + "'";
  }

  /// One record from i; false (with an error, `stop` where it was found) when it is malformed.
  bool parseRecord(std::size_t i, ParsedRecord& r, std::size_t& stop) {
    r.begin = static_cast<std::uint32_t>(i);
    for (int f = 0; f < 3; ++f) {
      i = skipInline(i);
      if (i >= t_.size() || upper(t_[i]) != 'B') {
        stop = i;
        const bool digit = i < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i]));
        const char* names[] = {"x", "y", "J"};
        if (digit)
          diags_.error(Code::ThreeBSyntax, &src_, span(i, i + 1),
                       std::string("a lost B: the ") + names[f] + " field starts with a number, not with B",
                       "a 3B record is B x B y B J G Z; every field begins with B (an empty field is a bare B)");
        else
          diags_.error(Code::ThreeBSyntax, &src_, span(i, i + 1),
                       "expected B (the " + std::string(names[f]) + " field of a 3B record), found " + shown(i),
                       "a 3B record is B x B y B J G Z, for example B9900 B0 B9900 GX L3");
        return false;
      }
      r.fieldAt[static_cast<std::size_t>(f)] = static_cast<std::uint32_t>(i);
      i = skipInline(i + 1);
      const std::size_t digits = i;
      std::uint64_t value = 0;
      while (i < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i]))) {
        if (i - digits >= 10) {
          stop = i;
          diags_.error(Code::NumberOutOfRange, &src_, span(digits, i + 1),
                       "a 3B field longer than 10 digits (" + std::string(t_.substr(digits, 11)) + "…)",
                       "3B fields are micrometres: 10 digits are already 10 km");
          return false;
        }
        value = value * 10 + static_cast<std::uint64_t>(t_[i] - '0');
        ++i;
      }
      if (i < t_.size() && (t_[i] == '-' || t_[i] == '+' || t_[i] == '.' || t_[i] == ',')) {
        stop = i;
        diags_.error(Code::ThreeBSyntax, &src_, span(i, i + 1),
                     t_[i] == '-' || t_[i] == '+'
                         ? std::string("a sign in a 3B field: x, y and J are unsigned; the sign lives in Z")
                         : std::string("a decimal point in a 3B field: x, y and J are whole micrometres"),
                     "write B9900, not B-9.9; L1-L4 and SR/NR1-4 carry the quadrant");
        return false;
      }
      r.field[static_cast<std::size_t>(f)] = value;
    }
    i = skipInline(i);
    if (i >= t_.size() || upper(t_[i]) != 'G') {
      stop = i;
      diags_.error(Code::ThreeBSyntax, &src_, span(i, i + 1),
                   "expected the count direction GX or GY after the J field, found " + shown(i),
                   "a 3B record is B x B y B J G Z");
      return false;
    }
    const std::size_t g = i;
    i = skipInline(i + 1);
    if (i >= t_.size() || (upper(t_[i]) != 'X' && upper(t_[i]) != 'Y')) {
      stop = i;
      diags_.error(Code::ThreeBSyntax, &src_, span(g, i + 1), "unknown count direction: G must be followed by X or Y",
                   "GX counts J along x, GY along y");
      return false;
    }
    r.axis = upper(t_[i]) == 'X' ? Axis::X : Axis::Y;
    r.axisAt = static_cast<std::uint32_t>(g);
    i = skipInline(i + 1);
    r.zAt = static_cast<std::uint32_t>(i);
    const std::size_t z = i;
    bool ok = false;
    if (i < t_.size() && upper(t_[i]) == 'L') {
      ++i;
      ok = true;
    } else if (i + 1 < t_.size() && (upper(t_[i]) == 'S' || upper(t_[i]) == 'N') && upper(t_[i + 1]) == 'R') {
      r.arc = true;
      r.ccw = upper(t_[i]) == 'N';
      i += 2;
      ok = true;
    }
    if (ok && i < t_.size() && t_[i] >= '1' && t_[i] <= '4') {
      r.quadrant = t_[i] - '0';
      ++i;
    } else {
      std::size_t e = z;
      while (e < t_.size() && std::isalnum(static_cast<unsigned char>(t_[e])) && e - z < 4) ++e;
      stop = z;
      diags_.error(
          Code::ThreeBSyntax, &src_, span(z, e),
          "unknown Z '" + std::string(t_.substr(z, e - z)) + "': a 3B record ends with L1-L4, SR1-SR4 or NR1-NR4",
          "L: a line, by its end's quadrant; SR: a clockwise arc, NR: counter-clockwise, by its start's quadrant");
      return false;
    }
    if (i < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i]))) {
      stop = i;
      diags_.error(Code::ThreeBSyntax, &src_, span(z, i + 1),
                   "unknown Z '" + std::string(t_.substr(z, i + 1 - z)) + "': the quadrant is one digit, 1 to 4");
      return false;
    }
    r.end = static_cast<std::uint32_t>(i);
    stop = i;
    return true;
  }

  Move moveFor(const ParsedRecord& r) const {
    Move m;
    m.modes = kModeIncremental;  // each record is relative to where the last one ended
    m.span = SourceSpan{r.begin, r.end - r.begin};
    m.line = src_.locate(r.begin).line;
    return m;
  }

  void apply(const ParsedRecord& r) {
    constexpr double kMm = 1e-3;
    const double x = static_cast<double>(r.field[0]), y = static_cast<double>(r.field[1]);
    const double j = static_cast<double>(r.field[2]);
    const Vec2 signs = three_b::quadrantSigns(r.quadrant);
    Move m = moveFor(r);
    Vec2 centreWords(0, 0);  // x y as written, for an arc
    const SourceSpan jSpan = span(r.fieldAt[2], r.axisAt);
    if (!r.arc) {
      Vec2 d;
      if (j == 0) {
        diags_.warning(Code::ZeroLengthMove, &src_, m.span, "a 3B line with J = 0 moves nothing");
        return;
      }
      if (x == 0 && y == 0) {  // along an axis, given by L alone
        static const Vec2 dirs[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        d = dirs[r.quadrant - 1] * j;
        const Axis expected = (r.quadrant == 1 || r.quadrant == 3) ? Axis::X : Axis::Y;
        if (r.axis != expected) {
          diags_.error(Code::CountContradicts, &src_, span(r.axisAt, r.zAt),
                       std::string("J counts along ") + (r.axis == Axis::X ? "x" : "y") +
                           ", but a line with x = y = 0 and L" + std::to_string(r.quadrant) + " runs along " +
                           (expected == Axis::X ? "x" : "y"),
                       "L1 and L3 run along x (GX), L2 and L4 along y (GY)");
          return;
        }
      } else {
        const double along = r.axis == Axis::X ? x : y;
        if (along == 0) {
          diags_.error(Code::CountContradicts, &src_, span(r.axisAt, r.zAt),
                       std::string("J counts along ") + (r.axis == Axis::X ? "x, but x is 0" : "y, but y is 0") +
                           ": the line never moves that way, so J can never be reached",
                       "count along the larger component (GX when x > y)");
          return;
        }
        const double scale = j / along;  // x y give the direction; J the length along the count axis
        d = Vec2(signs.x() * x * scale, signs.y() * y * scale);
      }
      m.kind = MoveKind::Line;
      m.lower = geometry::Segment::line(position_, onGrid(position_ + d * kMm));
    } else {
      if (x == 0 && y == 0) {
        diags_.error(Code::ZeroRadius, &src_, span(r.fieldAt[0], r.fieldAt[2]),
                     "a 3B arc whose start is its centre (x = y = 0): the radius is 0");
        return;
      }
      const Vec2 startRel(signs.x() * x, signs.y() * y);
      const double radius = startRel.norm();
      Vec2 endRel;
      double sweep = 0.0;
      if (j == 0) {
        diags_.warning(Code::ZeroLengthMove, &src_, m.span, "a 3B arc with J = 0 moves nothing");
        return;
      }
      if (!three_b::arcEnd(startRel, r.ccw, r.axis, j, 1.0, endRel, sweep)) {
        diags_.error(Code::CountPastFullCircle, &src_, jSpan,
                     "J = " + std::to_string(r.field[2]) + " µm runs past a full circle: a full turn of this arc (R " +
                         formatFixed(radius * kMm, 3) + " mm) counts " + formatFixed(4 * radius, 0) + " µm",
                     "J is the travel along the count axis over every quadrant the arc crosses, at most 4 R");
        return;
      }
      const Vec2 centre = position_ - startRel * kMm;
      const Vec2 end = onGrid(centre + endRel * kMm);
      m.kind = MoveKind::Arc;
      m.lower = geometry::Segment::arc(
          position_, end, centre, r.ccw ? geometry::ArcDirection::CounterClockwise : geometry::ArcDirection::Clockwise);
      m.centreForm = CentreForm::Reversed;  // x y are the start minus the centre
      centreWords = startRel * kMm;
      // A count that ends where the other axis is the faster one puts the end imprecisely.
      if (three_b::arcAxis(endRel.x(), endRel.y()) != r.axis &&
          std::abs(std::abs(endRel.x()) - std::abs(endRel.y())) > 1.0)
        diags_.note(Code::CountContradicts, &src_, span(r.axisAt, r.zAt),
                    std::string("the arc ends nearer the ") + (r.axis == Axis::X ? "x" : "y") +
                        " axis, where its count coordinate hardly changes: the end is less precise than with " +
                        (r.axis == Axis::X ? "GY" : "GX"),
                    "3B counts along the axis whose coordinate changes faster at the end (|xe| > |ye|: GY)");
    }
    position_ = m.lower.end;
    path_.moves.push_back(std::move(m));
    path_.centreWords.push_back(centreWords);
  }

  /// The machine moves in whole micrometres from where it started: every record ends on that grid.
  Vec2 onGrid(const Vec2& p) const {
    const Vec2 d = (p - path_.start) * 1000.0;
    return path_.start + Vec2(std::round(d.x()), std::round(d.y())) / 1000.0;
  }

  const SourceFile& src_;
  std::string_view t_;
  Diagnostics& diags_;
  Vec2 position_;
  Toolpath path_;
};

}  // namespace

Toolpath readThreeB(const SourceFile& source, const ThreeBOptions& options, Diagnostics& diags) {
  return ThreeBReader(source, options, diags).run();
}

}  // namespace kerf::converter
