// DXF reader (read_dxf.h, docs/dxf.md). Group codes and their value types follow the DXF reference's
// "group code value types" table; binary DXF as it describes it (after the 22-byte sentinel, a
// 2-byte little-endian group code — 1 byte in R12, 255 escaping a 2-byte one — then the value:
// strings NUL-terminated, floats 8 bytes, integers 2, 4 or 8 bytes, booleans 1 byte, binary
// chunks a length byte and the bytes).
// Sections: 1. group codes and tags, ASCII and binary  2. entities as read
//           3. sections: header, blocks, entities  4. budgets and ranges
//           5. elements: lines, arcs, polylines, curves  6. inserts  7. detection and the entry point
#include "kerf/converter/formats/dxf/read_dxf.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/biarc.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <set>

namespace kerf::converter {

namespace {

using geometry::kPi;
using geometry::Segment;
using geometry::Vec2;

enum class ValueType { String, Double, Int16, Int32, Int64, Bool, Binary };

// ---- 1. group codes and tags, ASCII and binary --------------------------------------------------

ValueType typeOf(int code) {
  if ((code >= 10 && code <= 59) || (code >= 110 && code <= 149) || (code >= 210 && code <= 239) ||
      (code >= 460 && code <= 469) || (code >= 1010 && code <= 1059))
    return ValueType::Double;
  if ((code >= 60 && code <= 79) || (code >= 170 && code <= 179) || (code >= 270 && code <= 289) ||
      (code >= 370 && code <= 389) || (code >= 400 && code <= 409) || (code >= 1060 && code <= 1070))
    return ValueType::Int16;
  if ((code >= 90 && code <= 99) || (code >= 420 && code <= 429) || (code >= 440 && code <= 459) || code == 1071)
    return ValueType::Int32;
  if (code >= 160 && code <= 169) return ValueType::Int64;
  if (code >= 290 && code <= 299) return ValueType::Bool;
  if ((code >= 310 && code <= 319) || code == 1004) return ValueType::Binary;
  return ValueType::String;
}

struct Tag {
  int code = 0;
  std::string_view text;     ///< strings (and, in ASCII files, every value as written)
  double number = 0.0;       ///< numbers
  std::uint32_t where = 0;   ///< ASCII: the code's line; binary: the code's byte offset
  std::uint32_t offset = 0;  ///< the value's byte offset (for spans)
  std::uint32_t length = 0;
};

class TagReader {
 public:
  TagReader(const SourceFile& src, Diagnostics& diags) : src_(src), diags_(diags) {}

  /// Every tag of the file; false (with an error reported) when it is malformed.
  bool read(std::vector<Tag>& tags, bool& binary) {
    const std::string_view t = src_.text();
    binary = t.substr(0, kBinaryDxfSentinel.size()) == kBinaryDxfSentinel;
    return binary ? readBinary(t, tags) : readAscii(t, tags);
  }

  void error(std::uint32_t where, int code, bool binary, const std::string& what, SourceSpan span = {}) {
    std::string at = binary ? "at byte " + std::to_string(where) + ", " : "";
    diags_.error(Code::DxfSyntax, &src_, binary || span.length == 0 ? SourceSpan::wholeFile() : span,
                 at + (code >= 0 ? "group code " + std::to_string(code) + ": " : "") + what,
                 "a DXF file is pairs of lines: a group code (an integer), then its value");
  }

 private:
  bool readAscii(std::string_view t, std::vector<Tag>& tags) {
    std::size_t pos = 0;
    std::uint32_t line = 0;
    // Lines end at LF, CR LF or a lone CR (old Mac files), as SourceFile counts them.
    auto nextLine = [&](std::string_view& out, std::uint32_t& start) {
      if (pos >= t.size()) return false;
      start = static_cast<std::uint32_t>(pos);
      std::size_t e = t.find_first_of("\r\n", pos);
      if (e == std::string_view::npos) e = t.size();
      out = t.substr(pos, e - pos);
      pos = e + (e + 1 < t.size() && t[e] == '\r' && t[e + 1] == '\n' ? 2 : 1);
      ++line;
      return true;
    };
    while (true) {
      std::string_view codeText, value;
      std::uint32_t codeStart = 0, valueStart = 0;
      if (!nextLine(codeText, codeStart)) break;
      const std::uint32_t codeLine = line;
      const std::string_view c = trimBlanks(codeText);
      if (c.empty() && pos >= t.size()) break;  // a final empty line
      int code = 0;
      const auto r = std::from_chars(c.data(), c.data() + c.size(), code);
      if (c.empty() || r.ec != std::errc() || r.ptr != c.data() + c.size() || code < 0 || code > 1071) {
        // Bytes that are not text are not quoted: they would garble the terminal and the reports.
        const bool text = std::all_of(c.begin(), c.end(), [](char ch) { return ch >= 0x20 && ch < 0x7F; });
        error(codeLine, -1, false,
              c.empty() ? std::string("an empty line where a group code belongs")
              : text    ? "'" + std::string(c.substr(0, 40)) + "' is not a group code"
                        : std::string("bytes that are not text where a group code belongs: not a DXF file"),
              {codeStart, static_cast<std::uint32_t>(std::max<std::size_t>(codeText.size(), 1))});
        return false;
      }
      if (!nextLine(value, valueStart)) {
        error(codeLine, code, false, "the file ends after a group code, without its value: it is truncated",
              {codeStart, static_cast<std::uint32_t>(codeText.size())});
        return false;
      }
      Tag tag;
      tag.code = code;
      tag.where = codeLine;
      tag.offset = valueStart;
      tag.length = static_cast<std::uint32_t>(value.size());
      const ValueType type = typeOf(code);
      if (type == ValueType::String || type == ValueType::Binary) {
        tag.text = type == ValueType::String ? trimBlanks(value) : value;
      } else {
        tag.text = trimBlanks(value);
        if (!parseNumberField(value, tag.number)) {
          error(line, code, false, "'" + std::string(trimBlanks(value).substr(0, 40)) + "' is not a number",
                {valueStart, static_cast<std::uint32_t>(value.size())});
          return false;
        }
      }
      tags.push_back(tag);
      if (code == 0 && tag.text == "EOF") break;
    }
    return true;
  }

  bool readBinary(std::string_view t, std::vector<Tag>& tags) {
    std::size_t pos = kBinaryDxfSentinel.size();
    // R13 and later: 2-byte group codes (the first, 0, is two zero bytes); R12: 1 byte.
    const bool wide = pos + 1 < t.size() && t[pos] == 0 && t[pos + 1] == 0;
    auto need = [&](std::size_t n, std::uint32_t at, int code) {
      if (pos + n <= t.size()) return true;
      error(at, code, true, "the file ends inside a value: it is truncated");
      return false;
    };
    auto u8 = [&](std::size_t at) { return static_cast<std::uint8_t>(t[at]); };
    // A little-endian integer of T's width (this machine's order) into tag.number.
    auto integer = [&](auto zero, Tag& tag, std::uint32_t at) {
      decltype(zero) v;
      if (!need(sizeof v, at, tag.code)) return false;
      std::memcpy(&v, t.data() + pos, sizeof v);
      tag.number = static_cast<double>(v);
      pos += sizeof v;
      return true;
    };
    while (pos < t.size()) {
      const auto at = static_cast<std::uint32_t>(pos);
      int code;
      if (wide) {
        if (!need(2, at, -1)) return false;
        code = u8(pos) | (u8(pos + 1) << 8);
        pos += 2;
      } else {
        code = u8(pos++);
        if (code == 255) {
          if (!need(2, at, -1)) return false;
          code = u8(pos) | (u8(pos + 1) << 8);
          pos += 2;
        }
      }
      Tag tag;
      tag.code = code;
      tag.where = at;
      tag.offset = static_cast<std::uint32_t>(pos);
      switch (typeOf(code)) {
        case ValueType::String: {
          const std::size_t e = t.find('\0', pos);
          if (e == std::string_view::npos) {
            error(at, code, true, "a string without its terminating NUL: the file is truncated");
            return false;
          }
          tag.text = t.substr(pos, e - pos);
          pos = e + 1;
          break;
        }
        case ValueType::Double: {
          if (!need(8, at, code)) return false;
          double v;
          std::memcpy(&v, t.data() + pos, 8);  // little-endian, as this machine
          tag.number = v;
          pos += 8;
          if (!std::isfinite(v)) {
            error(at, code, true, "a number that is not finite");
            return false;
          }
          break;
        }
        case ValueType::Int16:
          if (!integer(std::int16_t{}, tag, at)) return false;
          break;
        case ValueType::Int32:
          if (!integer(std::int32_t{}, tag, at)) return false;
          break;
        case ValueType::Int64:
          if (!integer(std::int64_t{}, tag, at)) return false;
          break;
        case ValueType::Bool:
          if (!need(1, at, code)) return false;
          tag.number = u8(pos++);
          break;
        case ValueType::Binary: {
          if (!need(1, at, code)) return false;
          const std::size_t n = u8(pos++);
          if (!need(n, at, code)) return false;
          tag.text = t.substr(pos, n);
          pos += n;
          break;
        }
      }
      tags.push_back(tag);
      if (code == 0 && tag.text == "EOF") break;
    }
    return true;
  }

  const SourceFile& src_;
  Diagnostics& diags_;
};

// ---- 2. entities as read ------------------------------------------------------------------------

/// One entity: its type, its own tags, and (POLYLINE) its VERTEX entities.
struct Entity {
  std::string_view type;
  std::uint32_t where = 0;
  SourceSpan span;
  std::vector<Tag> tags;
  std::vector<Entity> children;

  [[nodiscard]] const Tag* find(int code) const {
    for (const Tag& t : tags)
      if (t.code == code) return &t;
    return nullptr;
  }
  [[nodiscard]] double number(int code, double fallback = 0.0) const {
    const Tag* t = find(code);
    return t ? t->number : fallback;
  }
  [[nodiscard]] std::string_view text(int code) const {
    const Tag* t = find(code);
    return t ? t->text : std::string_view{};
  }
};

/// Kerf's range for drawings: points and sizes within this many mm of the origin (a kilometre; the
/// ISO reader's numbers stop at 1e9 in their own unit), INSERT scales within this factor, arrays of
/// at most this many rows or columns (K0132).
constexpr double kLargestCoordinate = 1e6;
constexpr double kLargestScale = 1e6;
constexpr double kLargestArray = 1e6;

/// `to` moved by whole turns to the first value above `from` + eps, for angles within two turns
/// of each other (both reduced by fmod): at most two steps, never a loop over the turns.
double nextAbove(double from, double to, double eps) {
  for (int k = 0; k < 3 && to <= from + eps; ++k) to += 2 * kPi;
  return to;
}

/// A value refused as out of range, for its message: three decimals while it is small enough to
/// read so, else in exponent form (1e300 is not 300 digits long).
std::string outOfRange(double v) {
  if (std::isfinite(v) && std::abs(v) < 1e9) return formatFixed(v, 3);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

std::string outOfRange(const Vec2& p) { return "(" + outOfRange(p.x()) + ", " + outOfRange(p.y()) + ")"; }

/// A number read as an integer (a flag, a count, a degree): rounded when it lies within
/// +-2^31 - 1, else `fallback`; never cast out of int's range.
int asInteger(double v, int fallback) {
  return std::isfinite(v) && std::abs(v) <= 2147483647.0 ? static_cast<int>(std::lround(v)) : fallback;
}

struct DxfBlock {  // a BLOCK section entry: its base point and its entities
  Vec2 base{0, 0};
  std::vector<Entity> entities;
};

/// An affine map of the plane: p -> m p + t.
struct Affine {
  Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
  Vec2 t{0, 0};

  [[nodiscard]] Vec2 operator()(const Vec2& p) const { return m * p + t; }
  [[nodiscard]] Affine then(const Affine& outer) const { return {outer.m * m, outer.m * t + outer.t}; }
  [[nodiscard]] bool mirrored() const { return m.determinant() < 0; }
  /// Uniform scale (a similarity): the scale; nothing otherwise.
  [[nodiscard]] std::optional<double> similarity() const {
    const double a = m.col(0).norm(), b = m.col(1).norm();
    if (std::abs(a - b) > 1e-9 * std::max(a, b) || std::abs(m.col(0).dot(m.col(1))) > 1e-9 * a * b) return {};
    return a;
  }
};

/// The object coordinate system of an entity whose extrusion is -Z: x mirrored (the arbitrary
/// axis algorithm gives the OCS x axis as -X when the normal is (0, 0, -1)).
std::optional<Affine> ocsOf(const Entity& e, bool& tilted) {
  const double nx = e.number(210, 0.0), ny = e.number(220, 0.0), nz = e.number(230, 1.0);
  tilted = false;
  if (std::abs(nx) < 1e-9 && std::abs(ny) < 1e-9) {
    Affine a;
    if (nz < 0) a.m(0, 0) = -1;
    return a;
  }
  tilted = true;
  return std::nullopt;
}

// ---- 3. sections: header, blocks, entities ------------------------------------------------------

class DrawingReader {
 public:
  DrawingReader(const SourceFile& src, const DxfOptions& o, Diagnostics& d) : src_(src), o_(o), diags_(d) {}

  Drawing read() {
    TagReader tr(src_, diags_);
    std::vector<Tag> tags;
    if (!tr.read(tags, drawing_.binary)) return std::move(drawing_);
    binary_ = drawing_.binary;
    std::vector<Entity> model;
    std::size_t i = 0;
    bool sawEof = false;
    while (i < tags.size()) {
      const Tag& t = tags[i];
      if (t.code == 0 && t.text == "EOF") {
        sawEof = true;
        break;
      }
      if (t.code == 0 && t.text == "SECTION") {
        ++i;
        std::string_view name;
        if (i < tags.size() && tags[i].code == 2) name = tags[i++].text;
        if (name == "HEADER")
          i = header(tags, i);
        else if (name == "BLOCKS")
          i = blocks(tags, i);
        else if (name == "ENTITIES")
          i = entities(tags, i, model, true);
        else
          i = skipSection(tags, i);
        continue;
      }
      ++i;
    }
    if (!sawEof) {
      const Tag* last = tags.empty() ? nullptr : &tags.back();
      const std::uint32_t where = !last ? 0 : binary_ ? last->where : src_.locate(last->offset).line;
      tr.error(where, -1, binary_,
               "the file ends at " + std::string(binary_ ? "byte " : "line ") + std::to_string(where) +
                   " without `0 EOF`: it is truncated, and what follows is missing",
               last ? SourceSpan{last->offset, last->length} : SourceSpan{});
    }
    units();
    for (const Entity& e : model) {
      if (e.number(67, 0) == 1) continue;  // paper space
      ++drawing_.entities[std::string(e.type)];
      emit(e, Affine{}, 0);
    }
    if (!drawing_.skipped.empty()) {
      std::string list;
      for (const auto& [type, n] : drawing_.skipped)
        list += (list.empty() ? "" : ", ") + type + " " + std::to_string(n);
      diags_.note(Code::DxfSkipped, &src_, SourceSpan::wholeFile(),
                  "entities that carry no contour were skipped: " + list);
    }
    drawing_.ok = true;
    return std::move(drawing_);
  }

 private:
  std::size_t skipSection(const std::vector<Tag>& tags, std::size_t i) {
    while (i < tags.size() && !(tags[i].code == 0 && (tags[i].text == "ENDSEC" || tags[i].text == "EOF"))) ++i;
    return i < tags.size() && tags[i].text == "ENDSEC" ? i + 1 : i;
  }

  std::size_t header(const std::vector<Tag>& tags, std::size_t i) {
    for (; i < tags.size(); ++i) {
      const Tag& t = tags[i];
      if (t.code == 0) break;
      if (t.code == 9 && i + 1 < tags.size()) {
        if (t.text == "$ACADVER") drawing_.version = std::string(tags[i + 1].text);
        if (t.text == "$INSUNITS") drawing_.insUnits = asInteger(tags[i + 1].number, -1);
      }
    }
    return skipSection(tags, i);
  }

  /// Entities from tags[i] up to ENDSEC (or ENDBLK inside a block); i is left after the end.
  std::size_t entities(const std::vector<Tag>& tags, std::size_t i, std::vector<Entity>& out, bool section) {
    while (i < tags.size()) {
      const Tag& t = tags[i];
      if (t.code != 0) {
        ++i;
        continue;
      }
      if (t.text == "ENDSEC" && section) return i + 1;
      if (t.text == "ENDBLK" && !section) return i;
      if (t.text == "EOF") return i;
      Entity e = collect(tags, i);
      if (e.type == "POLYLINE" || (e.type == "INSERT" && e.number(66, 0) == 1)) {
        // VERTEX (or ATTRIB) entities up to SEQEND belong to it.
        while (i < tags.size() && tags[i].code == 0 && tags[i].text != "SEQEND" && tags[i].text != "ENDSEC" &&
               tags[i].text != "ENDBLK" && tags[i].text != "EOF") {
          Entity child = collect(tags, i);
          if (e.type == "POLYLINE" && child.type == "VERTEX") e.children.push_back(std::move(child));
          if (child.type != "VERTEX" && child.type != "ATTRIB") {
            // An entity the sequence should not hold: the SEQEND is missing. Keep it as its own.
            out.push_back(std::move(e));
            e = std::move(child);
            break;
          }
        }
        if (i < tags.size() && tags[i].code == 0 && tags[i].text == "SEQEND") collect(tags, i);
      }
      if (e.type == "SEQEND" || e.type == "VERTEX" || e.type == "ATTRIB") continue;
      out.push_back(std::move(e));
    }
    return i;
  }

  Entity collect(const std::vector<Tag>& tags, std::size_t& i) {
    Entity e;
    e.type = tags[i].text;
    e.where = tags[i].where;
    e.span = {tags[i].offset, tags[i].length};
    ++i;
    while (i < tags.size() && tags[i].code != 0) e.tags.push_back(tags[i++]);
    return e;
  }

  std::size_t blocks(const std::vector<Tag>& tags, std::size_t i) {
    while (i < tags.size()) {
      const Tag& t = tags[i];
      if (t.code == 0 && (t.text == "ENDSEC" || t.text == "EOF")) return t.text == "ENDSEC" ? i + 1 : i;
      if (t.code == 0 && t.text == "BLOCK") {
        Entity head = collect(tags, i);
        DxfBlock b;
        b.base = Vec2(head.number(10), head.number(20));
        i = entities(tags, i, b.entities, false);
        if (i < tags.size() && tags[i].text == "ENDBLK") collect(tags, i);
        blocks_[std::string(head.text(2))] = std::move(b);
        continue;
      }
      ++i;
    }
    return i;
  }

  void units() {
    static const std::pair<int, double> table[] = {
        {1, 25.4},   {2, 304.8},  {3, 1609344.0}, {4, 1.0},   {5, 10.0},  {6, 1000.0}, {7, 1e6},  {8, 2.54e-5},
        {9, 0.0254}, {10, 914.4}, {11, 1e-7},     {12, 1e-6}, {13, 1e-3}, {14, 100.0}, {15, 1e4}, {16, 1e5}};
    const char* names[] = {"unitless",   "inches",     "feet",        "miles",      "millimetres", "centimetres",
                           "metres",     "kilometres", "microinches", "mils",       "yards",       "angstroms",
                           "nanometres", "microns",    "decimetres",  "decametres", "hectometres"};
    std::optional<double> fileScale;
    for (const auto& [u, s] : table)
      if (u == drawing_.insUnits) fileScale = s;
    const std::string said = drawing_.insUnits >= 0 && drawing_.insUnits <= 16
                                 ? std::string(names[drawing_.insUnits])
                                 : "unit " + std::to_string(drawing_.insUnits);
    if (o_.unitToMm > 0) {
      scale_ = o_.unitToMm;
      if (fileScale && std::abs(*fileScale - scale_) > 1e-12)
        diags_.note(Code::DxfUnits, &src_, SourceSpan::wholeFile(),
                    "the drawing's $INSUNITS says " + said + "; read with 1 unit = " + formatFixed(scale_, 6) +
                        " mm, as --dxf-units says",
                    "--dxf-units file scales by it");
    } else {
      scale_ = drawing_.insUnits == 0 ? 1.0 : fileScale.value_or(1.0);
      if (drawing_.insUnits == 0)
        diags_.note(Code::DxfUnits, &src_, SourceSpan::wholeFile(), "the drawing gives no unit ($INSUNITS): read in mm",
                    "--dxf-units in if it is drawn in inches");
      else if (!fileScale)
        diags_.note(Code::DxfUnits, &src_, SourceSpan::wholeFile(),
                    "the drawing's $INSUNITS (" + said + ") is not a unit Kerf knows: read in mm", "--dxf-units mm|in");
      else if (std::abs(scale_ - 1.0) > 1e-12)
        diags_.note(Code::DxfUnits, &src_, SourceSpan::wholeFile(),
                    "the drawing's $INSUNITS says " + said + ": read with 1 unit = " + formatFixed(scale_, 6) + " mm",
                    "--dxf-units mm if it is drawn in mm all the same");
    }
    drawing_.unitToMm = scale_;
  }

  // ---- 4. budgets and ranges --------------------------------------------------------------------

  /// A warning at the entity (binary: its byte offset in the message, there being no line).
  void warn(const Entity& e, const std::string& what) {
    diags_.warning(Code::DxfEntity, &src_, binary_ ? SourceSpan::wholeFile() : e.span,
                   std::string(e.type) + (binary_ ? " at byte " + std::to_string(e.where) : "") + ": " + what);
  }

  /// An entity beyond Kerf's range (K0132): an error at its line; the entity is left out.
  void refuse(const Entity& e, const std::string& what) {
    diags_.error(Code::DrawingOutOfRange, &src_, binary_ ? SourceSpan::wholeFile() : e.span,
                 std::string(e.type) + (binary_ ? " at byte " + std::to_string(e.where) : "") + ": " + what,
                 "Kerf reads drawings within 1e6 mm (a kilometre) of the origin");
  }

  /// Counts `n` more entity visits, the expansion of INSERT `e`, against the budget
  /// (DxfOptions::maxVisits); false, with one error at the INSERT that spends it.
  bool visit(const Entity& e, std::size_t n) {
    if (!overBudget_ && n <= o_.maxVisits - std::min(o_.maxVisits, visits_)) {
      visits_ += n;
      return true;
    }
    if (!overBudget_)
      diags_.error(Code::DxfEntity, &src_, binary_ ? SourceSpan::wholeFile() : e.span,
                   "INSERT" + (binary_ ? " at byte " + std::to_string(e.where) : std::string()) +
                       ": the drawing's INSERTs expand to more than " + std::to_string(o_.maxVisits) +
                       " entities: refused before expanding further");
    overBudget_ = true;
    return false;
  }

  /// The size of the box around points (its longer side), in their units.
  static double extentOf(const std::vector<Vec2>& points) {
    Vec2 lo = points.front(), hi = points.front();
    for (const Vec2& q : points) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    return (hi - lo).maxCoeff();
  }

  /// Whether a point of the drawing, in mm, lies within Kerf's range.
  static bool inRange(const Vec2& p) {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::abs(p.x()) <= kLargestCoordinate &&
           std::abs(p.y()) <= kLargestCoordinate;
  }

  bool room() {
    if (drawing_.elements.size() < o_.maxElements) return true;
    if (!overBudget_)
      diags_.error(Code::DxfEntity, &src_, SourceSpan::wholeFile(),
                   "the drawing expands to more than " + std::to_string(o_.maxElements) +
                       " lines and arcs (nested or arrayed INSERTs): refused before expanding further");
    overBudget_ = true;
    return false;
  }

  // ---- 5. elements: lines, arcs, polylines, curves ----------------------------------------------

  void add(const Entity& e, const std::string& layer, const Segment& s) {
    if (!inRange(s.start) || !inRange(s.end) ||
        (s.isArc() && (!inRange(s.centre) || !(s.radius() <= kLargestCoordinate)))) {
      const bool endsIn = inRange(s.start) && inRange(s.end);
      refuse(e, endsIn ? "an arc of radius " + outOfRange(s.radius()) + " mm about " + outOfRange(s.centre) +
                             " mm, beyond 1e6 mm"
                       : "it reaches " + outOfRange(inRange(s.start) ? s.end : s.start) + " mm, beyond 1e6 mm");
      return;
    }
    if (!room()) return;
    DrawingElement d;
    d.segment = s;
    d.entity = std::string(e.type);
    d.layer = layer;
    d.where = e.where;
    d.span = binary_ ? SourceSpan{0, 0} : e.span;
    drawing_.elements.push_back(std::move(d));
  }

  void addLine(const Entity& e, const std::string& layer, const Affine& a, Vec2 p, Vec2 q) {
    p = a(p) * scale_;
    q = a(q) * scale_;
    if ((q - p).norm() > 1e-12) add(e, layer, Segment::line(p, q));
  }

  /// An arc about c of radius r from angle a0 to a1 (radians, counter-clockwise in its own
  /// system), mapped by a.
  void addArc(const Entity& e, const std::string& layer, const Affine& a, Vec2 c, double r, double a0, double a1,
              bool full) {
    if (!(r > 0)) {
      warn(e, "radius " + formatFixed(r, 6) + ": no arc");
      return;
    }
    if (!(r * scale_ <= kLargestCoordinate)) {
      refuse(e, "a radius of " + outOfRange(r * scale_) + " mm, beyond 1e6 mm");
      return;
    }
    // Whole turns taken off in closed form (fmod is exact): a start angle of 1e20 costs nothing.
    a0 = std::fmod(a0, 2 * kPi);
    a1 = full ? a0 + 2 * kPi : nextAbove(a0, std::fmod(a1, 2 * kPi), 0.0);
    if (const std::optional<double> k = a.similarity()) {
      const Vec2 p = a(c + r * Vec2(std::cos(a0), std::sin(a0))) * scale_;
      const Vec2 q = full ? p : Vec2(a(c + r * Vec2(std::cos(a1), std::sin(a1))) * scale_);
      const auto dir = a.mirrored() ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise;
      add(e, layer, Segment::arc(p, q, a(c) * scale_, dir));
      return;
    }
    // Scaled unevenly: an elliptical arc, fitted with biarcs.
    geometry::ParametricCurve curve;
    const double s = scale_;
    curve.point = [a, c, r, s](double t) { return Vec2(a(c + r * Vec2(std::cos(t), std::sin(t))) * s); };
    curve.t0 = a0;
    curve.t1 = a1;
    addCurve(e, layer, curve);
  }

  void addCurve(const Entity& e, const std::string& layer, const geometry::ParametricCurve& curve) {
    geometry::BiarcOptions bo;
    bo.tolerance = o_.curveTolerance;
    bo.maxSpans = std::max<std::size_t>(1, o_.maxElements - std::min(o_.maxElements, drawing_.elements.size()));
    const geometry::BiarcFit fit = geometry::fitBiarcs(curve, bo);
    if (fit.overBudget) {
      room();
      warn(e, "the curve needs more arcs than the drawing may hold");
      return;
    }
    if (!fit.ok) warn(e, "the curve has a corner or a cusp the arcs cannot follow within the tolerance");
    for (const Segment& seg : fit.segments) add(e, layer, seg);
  }

  /// A polyline's vertices and bulges (bulge i belongs to the segment from vertex i).
  void addPolyline(const Entity& e, const std::string& layer, const Affine& a, const std::vector<Vec2>& v,
                   const std::vector<double>& bulge, bool closed) {
    const std::size_t n = v.size();
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
      const Vec2 p = v[i], q = v[(i + 1) % n];
      const double b = bulge[i];
      if ((q - p).norm() <= 1e-12) continue;
      if (std::abs(b) < 1e-12) {
        addLine(e, layer, a, p, q);
        continue;
      }
      // The arc whose included angle is 4 atan(b): > 0 counter-clockwise.
      const Vec2 chord = q - p, mid = 0.5 * (p + q);
      const Vec2 left(-chord.y(), chord.x());
      const Vec2 c = mid + left * ((1 - b * b) / (4 * b));
      const double r = (p - c).norm();
      const double a0 = std::atan2(p.y() - c.y(), p.x() - c.x()), a1 = std::atan2(q.y() - c.y(), q.x() - c.x());
      if (b > 0) {
        addArc(e, layer, a, c, r, a0, a1, false);
      } else {  // clockwise: the counter-clockwise arc from q to p, reversed
        const std::size_t before = drawing_.elements.size();
        addArc(e, layer, a, c, r, a1, a0, false);
        std::reverse(drawing_.elements.begin() + static_cast<std::ptrdiff_t>(before), drawing_.elements.end());
        for (std::size_t k = before; k < drawing_.elements.size(); ++k)
          drawing_.elements[k].segment = drawing_.elements[k].segment.reversed();
      }
    }
  }

  void emit(const Entity& e, const Affine& outer, int depth) {
    const std::string layer(e.text(8));
    const std::string_view type = e.type;
    bool tilted = false;
    const bool ocsEntity =
        type == "ARC" || type == "CIRCLE" || type == "LWPOLYLINE" || type == "POLYLINE" || type == "INSERT";
    Affine a = outer;
    if (ocsEntity) {
      const std::optional<Affine> ocs = ocsOf(e, tilted);
      if (tilted) {
        warn(e, "its plane is tilted out of the drawing's XY plane: not a contour Kerf reads");
        return;
      }
      a = ocs->then(outer);
    }
    if (type == "LINE") {
      addLine(e, layer, a, {e.number(10), e.number(20)}, {e.number(11), e.number(21)});
    } else if (type == "ARC" || type == "CIRCLE") {
      const bool circle = type == "CIRCLE";
      // Degrees reduced to one turn before they become radians (fmod is exact).
      const double a0 = circle ? 0.0 : std::fmod(e.number(50), 360.0) * kPi / 180;
      const double a1 = circle ? 0.0 : std::fmod(e.number(51), 360.0) * kPi / 180;
      const bool full = circle || std::abs(std::remainder(a1 - a0, 2 * kPi)) < 1e-12;
      addArc(e, layer, a, {e.number(10), e.number(20)}, e.number(40), a0, a1, full);
    } else if (type == "LWPOLYLINE") {
      std::vector<Vec2> v;
      std::vector<double> bulge;
      for (const Tag& t : e.tags) {
        if (t.code == 10) {
          v.emplace_back(t.number, 0.0);
          bulge.push_back(0.0);
        } else if (t.code == 20 && !v.empty()) {
          v.back().y() = t.number;
        } else if (t.code == 42 && !bulge.empty()) {
          bulge.back() = t.number;
        }
      }
      addPolyline(e, layer, a, v, bulge, (asInteger(e.number(70), 0) & 1) != 0);
    } else if (type == "POLYLINE") {
      const int flags = asInteger(e.number(70), 0);
      if (flags & (16 | 64)) {  // polygon and polyface meshes
        ++drawing_.skipped[std::string(type) + " (mesh)"];
        return;
      }
      std::vector<Vec2> v;
      std::vector<double> bulge;
      for (const Entity& vert : e.children) {
        const int vf = asInteger(vert.number(70), 0);
        if (vf & 16) continue;  // a spline frame's control point, not on the curve
        v.emplace_back(vert.number(10), vert.number(20));
        bulge.push_back(vert.number(42));
      }
      addPolyline(e, layer, a, v, bulge, (flags & 1) != 0);
    } else if (type == "ELLIPSE") {
      ellipse(e, layer, a);
    } else if (type == "SPLINE") {
      spline(e, layer, a);
    } else if (type == "INSERT") {
      insert(e, a, depth);
    } else {
      ++drawing_.skipped[std::string(type)];
    }
  }

  void ellipse(const Entity& e, const std::string& layer, const Affine& a) {
    const Vec2 c(e.number(10), e.number(20)), major(e.number(11), e.number(21));
    const double ratio = e.number(40, 1.0), nz = e.number(230, 1.0);
    if (std::abs(e.number(210)) > 1e-9 || std::abs(e.number(220)) > 1e-9) {
      warn(e, "its plane is tilted out of the drawing's XY plane: not a contour Kerf reads");
      return;
    }
    if (!(major.norm() > 0) || !(ratio > 0)) {
      warn(e, "an ellipse without size");
      return;
    }
    // The minor axis is the normal crossed with the major axis, scaled by the ratio.
    const Vec2 minor = (nz < 0 ? Vec2(major.y(), -major.x()) : Vec2(-major.y(), major.x())) * ratio;
    if (!(ratio <= 1.0 + 1e-9) || !inRange(c * scale_) ||
        !(std::hypot(major.x(), major.y()) * scale_ <= kLargestCoordinate)) {
      refuse(e, "an ellipse of ratio " + outOfRange(ratio) + " and major axis " +
                    outOfRange(std::hypot(major.x(), major.y()) * scale_) +
                    " mm: the ratio must be at most 1, the axes within 1e6 mm");
      return;
    }
    const double t0 = std::fmod(e.number(41, 0.0), 2 * kPi);
    const double t1 = nextAbove(t0, std::fmod(e.number(42, 2 * kPi), 2 * kPi), 1e-12);
    geometry::ParametricCurve curve;
    const double s = scale_;
    curve.point = [=](double t) { return Vec2(a(c + std::cos(t) * major + std::sin(t) * minor) * s); };
    curve.derivative = [=](double t) { return Vec2(a.m * (-std::sin(t) * major + std::cos(t) * minor) * s); };
    curve.t0 = t0;
    curve.t1 = t1;
    addCurve(e, layer, curve);
  }

  /// A SPLINE's points and weights within Kerf's range (K0132 at the entity otherwise), checked in
  /// closed form before any fitting (issue 41: a zero weight or a point at 1e308 kept the biarc
  /// fitter busy for a minute and then gave nothing).
  bool splineInRange(const Entity& e, const Affine& a, const std::vector<Vec2>& control, const std::vector<Vec2>& fit,
                     const std::vector<double>& weights) {
    for (const Vec2& q : control)
      if (!inRange(a(q) * scale_)) {
        refuse(e, "a control point at " + outOfRange(a(q) * scale_) + " mm, beyond 1e6 mm");
        return false;
      }
    for (const Vec2& q : fit)
      if (!inRange(a(q) * scale_)) {
        refuse(e, "a fit point at " + outOfRange(a(q) * scale_) + " mm, beyond 1e6 mm");
        return false;
      }
    for (const double w : weights)
      if (!(w > 0 && w <= kLargestScale)) {
        refuse(e, "a weight of " + outOfRange(w) + ": weights must lie in (0, 1e6]");
        return false;
      }
    return true;
  }

  /// A SPLINE given by its fit points alone: the cubic through them (geometry::fitPointList), as
  /// biarcs; at most kMostFitPoints, and refused when it swings far beyond its points.
  void fitPointSpline(const Entity& e, const std::string& layer, const Affine& a, const std::vector<Vec2>& fit) {
    if (fit.size() > geometry::kMostFitPoints) {
      refuse(e, std::to_string(fit.size()) + " fit points: Kerf fits a curve through at most " +
                    std::to_string(geometry::kMostFitPoints) + " (without control points and knots)");
      return;
    }
    std::vector<Vec2> pts;
    for (const Vec2& p : fit) pts.push_back(a(p) * scale_);
    geometry::BiarcOptions bo;
    bo.tolerance = o_.curveTolerance;
    const geometry::BiarcFit f = geometry::fitPointList(pts, bo);
    if (f.swings) {
      refuse(e, "the curve through its fit points swings out far beyond them (points very unevenly spaced)");
      return;
    }
    for (const Segment& seg : f.segments) add(e, layer, seg);
  }

  void spline(const Entity& e, const std::string& layer, const Affine& a) {
    const int degree = asInteger(e.number(71, 3), -1);
    std::vector<double> knots, weights;
    std::vector<Vec2> control, fit;
    for (const Tag& t : e.tags) {
      if (t.code == 40) knots.push_back(t.number);
      if (t.code == 41) weights.push_back(t.number);
      if (t.code == 10) control.emplace_back(t.number, 0.0);
      if (t.code == 20 && !control.empty()) control.back().y() = t.number;
      if (t.code == 11) fit.emplace_back(t.number, 0.0);
      if (t.code == 21 && !fit.empty()) fit.back().y() = t.number;
    }
    if (!splineInRange(e, a, control, fit, weights)) return;
    // Fit points repeated one after another add nothing: dropped.
    fit.erase(std::unique(fit.begin(), fit.end(), [](const Vec2& x, const Vec2& y) { return (x - y).norm() < 1e-12; }),
              fit.end());
    const std::size_t n = control.size();
    if (n > 0 && extentOf(control) * scale_ < o_.curveTolerance && fit.size() < 2) {
      warn(e, "its control points all lie within the curve tolerance of one point: a curve of no extent");
      return;
    }
    const bool nurbs = degree >= 1 && degree <= 11 && n >= static_cast<std::size_t>(degree) + 1 &&
                       knots.size() == n + static_cast<std::size_t>(degree) + 1 &&
                       std::is_sorted(knots.begin(), knots.end()) && (weights.empty() || weights.size() == n);
    if (!nurbs) {
      if (fit.size() >= 2) {
        fitPointSpline(e, layer, a, fit);
        return;
      }
      warn(e, "its control points, knots and weights do not make a curve (degree " + std::to_string(degree) + ", " +
                  std::to_string(n) + " control points, " + std::to_string(knots.size()) +
                  " knots), and it has fewer than two distinct fit points");
      return;
    }
    if (weights.empty()) weights.assign(n, 1.0);
    const auto p = static_cast<std::size_t>(degree);
    const double lo = knots[p], hi = knots[n];
    if (!(hi > lo)) {
      warn(e, "its knots span nothing");
      return;
    }
    // de Boor on the homogeneous points, shared by the pieces; no allocation per evaluation (the
    // biarc fitter evaluates thousands of times).
    struct Nurbs {
      std::vector<double> knots;
      std::vector<Eigen::Vector3d> homogeneous;
      std::size_t p;
    };
    auto curveData = std::make_shared<Nurbs>();
    curveData->knots = knots;
    curveData->p = p;
    for (std::size_t i = 0; i < n; ++i)
      curveData->homogeneous.emplace_back(control[i].x() * weights[i], control[i].y() * weights[i], weights[i]);
    auto eval = [curveData, a, s = scale_](double u) -> Vec2 {
      const Nurbs& c = *curveData;
      const std::size_t deg = c.p, count = c.homogeneous.size();
      // The knot span: the last k in [deg, count) with knots[k] <= u.
      const auto it = std::upper_bound(c.knots.begin() + static_cast<std::ptrdiff_t>(deg),
                                       c.knots.begin() + static_cast<std::ptrdiff_t>(count), u);
      const std::size_t k = std::max<std::size_t>(deg, static_cast<std::size_t>(it - c.knots.begin()) - 1);
      std::array<Eigen::Vector3d, 12> d;  // degree <= 11
      for (std::size_t j = 0; j <= deg; ++j) d[j] = c.homogeneous[k - deg + j];
      for (std::size_t r = 1; r <= deg; ++r)
        for (std::size_t j = deg; j >= r; --j) {
          const std::size_t i = k - deg + j;
          const double den = c.knots[i + deg + 1 - r] - c.knots[i];
          const double alpha = den > 0 ? (u - c.knots[i]) / den : 0.0;
          d[j] = (1 - alpha) * d[j - 1] + alpha * d[j];
        }
      return a(Vec2(d[deg].x() / d[deg].z(), d[deg].y() / d[deg].z())) * s;
    };
    // Split at knots of full multiplicity inside the domain: the curve may turn a corner there.
    std::vector<double> breaks{lo};
    for (std::size_t i = p + 1; i < n;) {
      std::size_t j = i;
      while (j < n && knots[j] == knots[i]) ++j;
      if (j - i >= p && knots[i] > lo && knots[i] < hi) breaks.push_back(knots[i]);
      i = j;
    }
    breaks.push_back(hi);
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
      geometry::ParametricCurve curve;
      curve.point = eval;
      curve.t0 = breaks[b];
      curve.t1 = breaks[b + 1];
      addCurve(e, layer, curve);
    }
  }

  // ---- 6. inserts -------------------------------------------------------------------------------

  void insert(const Entity& e, const Affine& a, int depth) {
    const std::string name(e.text(2));
    const auto it = blocks_.find(name);
    if (it == blocks_.end()) {
      warn(e, "block '" + name + "' is not defined in the file");
      return;
    }
    if (depth >= o_.maxInsertDepth) {  // said once a block: a deep tree would say it for every leaf
      if (tooDeep_.insert(name).second)
        warn(e, "INSERTs nested deeper than " + std::to_string(o_.maxInsertDepth) + " (a block that inserts itself?)");
      return;
    }
    const DxfBlock& b = it->second;
    const double sx = e.number(41, 1.0), sy = e.number(42, 1.0), rot = std::fmod(e.number(50), 360.0) * kPi / 180;
    const double colsWritten = e.number(70, 1), rowsWritten = e.number(71, 1);
    const double dc = e.number(44), dr = e.number(45);
    if (!(std::abs(sx) > 0 && std::abs(sx) <= kLargestScale && std::abs(sy) > 0 && std::abs(sy) <= kLargestScale)) {
      refuse(e, "a scale of " + outOfRange(sx) + " x " + outOfRange(sy) + ": 0, or beyond 1e6");
      return;
    }
    if (!(colsWritten <= kLargestArray && rowsWritten <= kLargestArray) || std::abs(dc) > kLargestCoordinate ||
        std::abs(dr) > kLargestCoordinate) {
      refuse(e, "an array of " + outOfRange(colsWritten) + " x " + outOfRange(rowsWritten) +
                    " copies, or a spacing beyond 1e6: refused before expanding");
      return;
    }
    const int cols = std::max(1, asInteger(colsWritten, 1)), rows = std::max(1, asInteger(rowsWritten, 1));
    // Every copy of every entity of the block is a visit (a text adds no element, a nested INSERT
    // a warning): the work is counted before it is done, as the G-code move budget is.
    if (!visit(e, static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows) *
                      std::max<std::size_t>(b.entities.size(), 1)))
      return;
    const Eigen::Matrix2d r = Eigen::Rotation2Dd(rot).toRotationMatrix();
    for (int row = 0; row < rows; ++row)
      for (int col = 0; col < cols; ++col) {
        Affine local;
        local.m = r * Eigen::DiagonalMatrix<double, 2>(sx, sy);
        local.t = Vec2(e.number(10), e.number(20)) + r * Vec2(col * dc, row * dr) - local.m * b.base;
        const Affine whole = local.then(a);
        for (const Entity& child : b.entities) {
          if (overBudget_) return;
          emit(child, whole, depth + 1);
        }
      }
  }

  const SourceFile& src_;
  const DxfOptions& o_;
  Diagnostics& diags_;
  Drawing drawing_;
  bool binary_ = false;
  bool overBudget_ = false;
  std::size_t visits_ = 0;         ///< entity visits through INSERTs so far (visit())
  std::set<std::string> tooDeep_;  ///< blocks already reported as nested too deep
  double scale_ = 1.0;
  std::map<std::string, DxfBlock> blocks_;
};

}  // namespace

// ---- 7. detection and the entry point -----------------------------------------------------------

bool looksLikeDxf(std::string_view text) {
  if (text.substr(0, kBinaryDxfSentinel.size()) == kBinaryDxfSentinel) return true;
  // Pairs of lines: skip 999 comments, then "0" and "SECTION".
  std::size_t pos = 0;
  auto line = [&]() {  // LF, CR LF or a lone CR
    std::size_t e = text.find_first_of("\r\n", pos);
    if (e == std::string_view::npos) e = text.size();
    std::string_view l = trimBlanks(text.substr(pos, e - pos));
    pos = std::min(text.size(), e + (e + 1 < text.size() && text[e] == '\r' && text[e + 1] == '\n' ? 2 : 1));
    return l;
  };
  for (int guard = 0; guard < 64 && pos < text.size(); ++guard) {
    const std::string_view code = line(), value = line();
    if (code == "999") continue;
    return code == "0" && value == "SECTION";
  }
  return false;
}

Drawing readDxf(const SourceFile& source, const DxfOptions& options, Diagnostics& diags) {
  return DrawingReader(source, options, diags).read();
}

}  // namespace kerf::converter
