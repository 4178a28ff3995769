// Normalised ISO (docs/formats.md, "Writing ISO"): absolute, one move per block, I J incremental,
// in the conventions of the target machine's profile (units, arc centres, block and line ends,
// the 4-axis dialect of a taper program).
#include "kerf/converter/formats/iso/write_iso.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/number_format.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {

namespace {

using geometry::Segment;
using geometry::Vec2;

class IsoWriter {
 public:
  IsoWriter(const MachineProfile& target, int decimals)
      : m_(target), decimals_(target.writeMicrometres ? 0 : decimals), scale_(target.writeMicrometres ? 1000.0 : 1.0) {}

  /// A coordinate rounded as it is written, in mm.
  [[nodiscard]] double rounded(double v) const {
    const double f = std::pow(10.0, decimals_) * scale_;
    return std::nearbyint(v * f) / f;
  }
  [[nodiscard]] Vec2 rounded(const Vec2& p) const { return {rounded(p.x()), rounded(p.y())}; }
  [[nodiscard]] std::string num(double v) const {
    std::string s = formatFixed(v * scale_, decimals_);
    // A whole number of mm keeps its point (X15.), as controls that read integers as µm need.
    if (!m_.writeMicrometres && decimals_ == 0) s += '.';
    return s;
  }

  void block(const std::string& words) {
    text_ += words;
    if (m_.semicolonEndsBlock) text_ += ';';
    text_ += m_.crlf ? "\r\n" : "\n";
  }
  void comment(const std::string& c) { block("(" + c + ")"); }

  /// mm: the smallest step the output writes.
  [[nodiscard]] double resolution() const { return 1.0 / (std::pow(10.0, decimals_) * scale_); }
  /// 2-axis output: an arc that bulges from its chord by less than half the resolution is written
  /// as the line it is at that resolution (a micro arc's rounded I J would give its ends radii that
  /// differ by more than the arc is long, which controllers refuse).
  bool flattenSlivers = true;

  /// The words of one side's motion: G X Y [I J] (names: X Y I J or U V I J).
  std::string motion(const Segment& arcOrLine, bool rapid, char a, char b, bool withG = true) const {
    const double sweep = std::abs(arcOrLine.sweep);
    const bool sliver = flattenSlivers && arcOrLine.isArc() && sweep < 2 * geometry::kPi - 1e-9 &&
                        arcOrLine.radius() * (1 - std::cos(sweep / 2)) < 0.5 * resolution();
    const Segment s = sliver ? Segment::line(arcOrLine.start, arcOrLine.end) : arcOrLine;
    std::string w;
    if (withG) {
      const char* g = rapid ? "G00 " : !s.isArc() ? "G01 " : s.sweep < 0 ? "G02 " : "G03 ";
      w = m_.writeShortG ? std::string("G") + g[2] + " " : std::string(g);
    }
    const Vec2 end = rounded(s.end);
    w += std::string(1, a) + num(end.x()) + " " + std::string(1, b) + num(end.y());
    if (s.isArc()) {
      const Vec2 start = rounded(s.start), centre = rounded(s.centre);
      Vec2 ij = centre - start;  // incremental
      if (m_.arcCentre == ArcCentreMode::Absolute) ij = centre;
      if (m_.arcCentre == ArcCentreMode::Reversed) ij = start - centre;
      w += " I" + num(ij.x()) + " J" + num(ij.y());
    }
    return w;
  }

  std::string text_;

 private:
  const MachineProfile& m_;
  int decimals_;
  double scale_;
};

const char* offsetCode(WireOffset o) {
  switch (o) {
    case WireOffset::Left: return "G41";
    case WireOffset::Right: return "G42";
    case WireOffset::Off: return "G40";
  }
  return "G40";
}

}  // namespace

namespace {

/// One program being written for a target, in the order its phases come: the header (comment and
/// heights), the start, the moves, the end. Holds what the phases share: the writer, the offset in
/// force, the start point the profile's blocks name.
struct IsoProgram {
  const Toolpath& toolpath;
  const MachineProfile& target;
  const SourceFile* source;
  Diagnostics& diags;
  IsoWriter w;
  bool taper = false;
  bool colon = false;         ///< Sodick's `lower : upper`
  bool blockOffsets = false;  ///< the offset goes on in blocks of its own
  Vec2 start{0, 0};
  WireOffset offset = WireOffset::Off;
  std::size_t written = 0;

  IsoProgram(const Toolpath& tp, const MachineProfile& m, const SourceFile* src, Diagnostics& d, int decimals)
      : toolpath(tp), target(m), source(src), diags(d), w(m, decimals) {
    taper = tp.isTaper();
    colon = taper && m.writeTaper == Dialect::SodickColon;
    blockOffsets = !m.writeOffset.empty();
    start = tp.moves.front().lower.start;
  }

  /// The profile's block template: {x} {y} the start, {g} the offset code.
  std::string expand(const std::string& tpl, const std::string& g) const {
    std::string out;
    for (std::size_t i = 0; i < tpl.size(); ++i) {
      if (tpl.compare(i, 3, "{x}") == 0) {
        out += w.num(w.rounded(start.x()));
        i += 2;
      } else if (tpl.compare(i, 3, "{y}") == 0) {
        out += w.num(w.rounded(start.y()));
        i += 2;
      } else if (tpl.compare(i, 3, "{g}") == 0) {
        out += g;
        i += 2;
      } else {
        out += tpl[i];
      }
    }
    return out;
  }
  void blocks(const std::vector<std::string>& templates) {
    for (const std::string& b : templates) w.block(expand(b, ""));
  }
  void offsetOn(WireOffset o) {
    for (const std::string& b : target.writeOffset) w.block(expand(b, offsetCode(o)));
  }
  void cancel() {
    if (target.writeCancel.empty())
      w.block("G40");
    else
      for (const std::string& b : target.writeCancel) w.block(expand(b, "G40"));
  }

  /// The comment that says how the program is written, and a taper's plane heights.
  void header() {
    const ArcCentreMode centres = target.arcCentre.value_or(ArcCentreMode::Incremental);
    if (target.writeComment)
      w.comment(std::string("written by Kerf for the ") + target.name + " machine from " +
                (source ? source->name() : std::string("a program")) + ": absolute, " +
                (target.writeMicrometres ? "micrometre integers" : "mm") + ", I J " +
                (centres == ArcCentreMode::Reversed ? arcCentreMeaning(centres) : arcCentreName(centres)) +
                (taper
                     ? std::string(", upper contour as ") + dialectName(colon ? Dialect::SodickColon : Dialect::XyuvAbs)
                     : std::string()));
    if (!taper) return;
    const PlaneHeights& h = toolpath.heights;
    if (!h.known) {
      diags.warning(Code::HeightsMissing, source, SourceSpan::wholeFile(),
                    "the plane heights are not known, so none are written: the output needs them as the input does",
                    "give --thickness H or --upper-z Z");
    } else if (colon) {  // Sodick: TN the lower plane, TP the program plane, taken as the upper plane
      w.block("TN" + w.num(h.planes.lower) + " TP" + w.num(h.planes.upper));
    } else {
      if (h.planes.lower != 0.0)
        diags.warning(Code::NotInOutputFormat, source, SourceSpan::wholeFile(),
                      "M101 P gives only the thickness: the lower plane (z " + formatFixed(h.planes.lower, 3) +
                          ") is written as z 0");
      w.block("M101 P" + formatFixed(h.planes.height(), 3));
    }
  }

  /// The start: absolute, mm, G92 at the first move's start (or the profile's start blocks).
  void startBlocks() {
    if (target.writeStart.empty()) {
      w.block(target.writeMicrometres ? "G90" : "G90 G21");
      std::string g92 = "G92 X" + w.num(w.rounded(start.x())) + " Y" + w.num(w.rounded(start.y()));
      if (taper && !colon) {
        const Vec2 u = toolpath.upper.front().start;
        g92 += " U" + w.num(w.rounded(u.x())) + " V" + w.num(w.rounded(u.y()));
      }
      w.block(g92);
    } else {
      for (const std::string& b : target.writeStart) {
        if (b != "{offset}") {
          w.block(expand(b, ""));
        } else if (blockOffsets && toolpath.moves.front().wireOffset != WireOffset::Off) {
          offset = toolpath.moves.front().wireOffset;
          offsetOn(offset);
        }
      }
    }
    if (colon) w.block("G141");
  }

  /// An arc shorter than the output's resolution (a corner arc of a few nanometres on a densely drawn
  /// contour) would be written with its end on its start: a full circle. It is left out; the next
  /// move starts where it ended, to the resolution. (A line of no length is written: it is
  /// harmless, and a program may have one, as a Z move.)
  bool vanishes(const Segment& s) const {
    return !s.isArc() || (w.rounded(s.start) == w.rounded(s.end) && std::abs(s.sweep) < 2 * geometry::kPi - 1e-9);
  }

  /// The offset code move m needs, as a word of its block or as the profile's blocks before it.
  std::string offsetChange(const Move& m) {
    if (m.wireOffset == offset) return {};
    std::string word;
    if (m.wireOffset == WireOffset::Off && !target.writeCancel.empty()) {
      cancel();
    } else if (m.wireOffset != WireOffset::Off && blockOffsets) {
      if (offset != WireOffset::Off) cancel();
      offsetOn(m.wireOffset);
    } else {
      word = std::string(offsetCode(m.wireOffset)) + " ";
    }
    offset = m.wireOffset;
    return word;
  }

  /// One block a move. Between contours (a rapid after a cut, with cuts to come) the wire is cut
  /// before the rapid and threaded again after it, as the profile writes it (write_wire_cut,
  /// write_wire_thread).
  void moves() {
    double feed = 0.0;
    std::size_t lastCut = 0;
    bool anyCut = false;
    for (std::size_t i = 0; i < toolpath.moves.size(); ++i)
      if (toolpath.moves[i].isCut()) lastCut = i, anyCut = true;
    bool rethread = false;  // the wire was cut: thread it before the next cut
    for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
      const Move& m = toolpath.moves[i];
      if (m.wireOffset == offset && m.lower.isArc() && vanishes(m.lower) && (!taper || vanishes(toolpath.upper[i])))
        continue;
      if (rethread && m.isCut()) {
        blocks(target.writeWireThread);
        rethread = false;
      }
      std::string words = offsetChange(m);
      const bool rapid = m.kind == MoveKind::Rapid;
      if (rapid && anyCut && i > 0 && toolpath.moves[i - 1].isCut() && i < lastCut) {
        blocks(target.writeWireCut);
        rethread = true;
      }
      words += w.motion(m.lower, rapid, 'X', 'Y');
      if (taper) {
        const Segment& u = toolpath.upper[i];
        if (colon)
          words += " : " + w.motion(u, rapid, 'X', 'Y');
        else
          words += " " + w.motion(u, rapid, 'U', 'V', !rapid);  // a rapid moves both sides alike
      }
      if (const double f = toolpath.feedOf(i); !rapid && f > 0 && f != feed) {
        words += " F" + formatFixed(f, 3);
        feed = f;
      }
      w.block(words);
      ++written;
    }
  }

  /// The end: the offset cancelled, M02 (or the profile's end blocks).
  void end() {
    if (colon) w.block("G140");
    if (target.writeEnd.empty()) {
      if (offset != WireOffset::Off) cancel();
      w.block("M02");
      return;
    }
    for (const std::string& b : target.writeEnd) {
      if (b != "{cancel}")
        w.block(expand(b, ""));
      else if (offset != WireOffset::Off)
        cancel();
    }
  }
};

}  // namespace

std::optional<EmitOutput> writeIso(const Toolpath& toolpath, const SourceFile* source, const IsoWriteOptions& request,
                                   Diagnostics& diags) {
  const MachineProfile& target = request.target ? *request.target : *findBuiltinMachine("generic");
  if (toolpath.moves.empty()) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(), "nothing to write: the program has no move");
    return std::nullopt;
  }
  const int decimals = request.decimals.value_or(target.writeDecimals);
  IsoProgram program(toolpath, target, source, diags, decimals);
  // kerf cam's own output only: a conversion keeps the program's arcs as written; the two sides of
  // a taper program must agree on G02/G03.
  program.w.flattenSlivers = request.flattenSlivers && !program.taper;
  program.header();
  program.startBlocks();
  program.moves();
  program.end();
  if (!request.offsetsApplied && std::any_of(toolpath.moves.begin(), toolpath.moves.end(),
                                             [](const Move& m) { return m.wireOffset != WireOffset::Off; }))
    diags.note(Code::NotInOutputFormat, source, SourceSpan::wholeFile(),
               std::string("G41/G42 are written ") +
                   (program.blockOffsets ? "as the machine profile writes them" : "without D or H") +
                   ": the offset value is the machine's");
  EmitOutput out;
  out.text = std::move(program.w.text_);
  out.what = std::to_string(program.written) + " blocks of ISO for the " + target.name + " machine";
  out.detail = target.writeMicrometres ? "; micrometre integers" : "; " + std::to_string(decimals) + " decimals";
  return out;
}

}  // namespace kerf::converter
