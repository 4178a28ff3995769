// The writer table (emit.h), and the plane a 2-axis file follows.
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/nc/number_format.h"

namespace kerf::converter {

std::optional<PlaneChoice> parsePlane(std::string_view text) {
  if (text == "lower") return PlaneChoice{PlaneChoice::Kind::Lower, 0.0};
  if (text == "upper") return PlaneChoice{PlaneChoice::Kind::Upper, 0.0};
  if (!text.starts_with("z=") || text.size() < 3) return std::nullopt;
  const std::string number(text.substr(2));
  char* end = nullptr;
  const double z = std::strtod(number.c_str(), &end);
  // Within a kilometre, as every coordinate Kerf reads.
  if (end != number.c_str() + number.size() || !(std::abs(z) <= 1e6)) return std::nullopt;
  return PlaneChoice{PlaneChoice::Kind::Height, z};
}

std::optional<Toolpath> toolpathAtPlane(const Toolpath& toolpath, const PlaneChoice& plane, double tolerance,
                                        const SourceFile* source, Diagnostics& diags) {
  Toolpath out;
  out.start = toolpath.start;
  out.programUnit = toolpath.programUnit;
  out.endedProperly = toolpath.endedProperly;
  out.heights = toolpath.heights;
  if (!toolpath.isTaper()) {
    out.feedChanges = toolpath.feedChanges;  // the same moves at their feeds
    out.moves = toolpath.moves;
    out.centreWords = toolpath.centreWords;
    return out;
  }
  double s = 0.0;
  if (plane.kind == PlaneChoice::Kind::Upper) s = 1.0;
  if (plane.kind == PlaneChoice::Kind::Height) {
    const geometry::Planes& p = toolpath.heights.planes;
    if (!toolpath.heights.known || plane.z < p.lower || plane.z > p.upper) {
      diags.error(Code::TaperFlattened, source, SourceSpan::wholeFile(),
                  toolpath.heights.known ? "z " + formatFixed(plane.z, 3) + " is outside the part (z " +
                                               formatFixed(p.lower, 3) + " .. " + formatFixed(p.upper, 3) + ")"
                                         : std::string("the plane heights are not known, so z= cannot be placed"));
      return std::nullopt;
    }
    s = (plane.z - p.lower) / p.height();
  }
  diags.warning(Code::TaperFlattened, source, SourceSpan::wholeFile(),
                "a 2-axis machine cannot cut the taper: this file follows the wire on one plane only (" +
                    std::string(plane.kind == PlaneChoice::Kind::Lower   ? "lower"
                                : plane.kind == PlaneChoice::Kind::Upper ? "upper"
                                                                         : "z " + formatFixed(plane.z, 3)) +
                    ")");
  out.start = (1.0 - s) * toolpath.moves.front().lower.start + s * toolpath.upper.front().start;
  std::vector<geometry::Segment> pieces;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    pieces.clear();
    if (s == 0.0)
      pieces.push_back(toolpath.moves[i].lower);
    else if (s == 1.0)
      pieces.push_back(toolpath.upper[i]);
    else
      geometry::appendSection(toolpath.moves[i].lower, toolpath.upper[i], s, tolerance, pieces);
    const double feed = toolpath.feedOf(i);
    for (const geometry::Segment& piece : pieces) {
      Move m = toolpath.moves[i];
      m.lower = piece;
      if (m.kind != MoveKind::Rapid) m.kind = piece.isArc() ? MoveKind::Arc : MoveKind::Line;
      out.setFeedFrom(out.moves.size(), feed);
      out.moves.push_back(m);
    }
  }
  return out;
}

namespace {

// Each row's write function: the request's part for its format, the start line where it takes one.
std::optional<EmitOutput> rowBp95d(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  PointWriteOptions o = r.points;
  o.request.startLine = r.startLine;
  return writeBp95d(t, s, o, d);
}
std::optional<EmitOutput> rowPoints4(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  PointWriteOptions o = r.points;
  o.request.startLine = r.startLine;
  return writePoints4(t, s, o, d);
}
std::optional<EmitOutput> rowThreeB(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  ThreeBWriteOptions o = r.threeB;
  o.startLine = r.startLine;
  return writeThreeB(t, s, o, d);
}
std::optional<EmitOutput> rowFourB(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  ThreeBWriteOptions o = r.threeB;
  o.startLine = r.startLine;
  return writeFourB(t, s, o, d);
}
std::optional<EmitOutput> rowIso(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  return writeIso(t, s, r.iso, d);
}
std::optional<EmitOutput> rowPolar(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  return writePolar(t, s, r.polar, d);
}
std::optional<EmitOutput> rowDxf(const Toolpath& t, const SourceFile* s, const EmitRequest& r, Diagnostics& d) {
  return writeDxfProgram(t, s, r.dxf, d);
}

}  // namespace

const std::vector<Emitter>& emitters() {
  static const std::vector<Emitter> table = {
      {"bp95d", "point sequence for point-driven 2-axis controllers (BP-95d): X Y per line, profile-driven",
       PlaneNeed::One, rowBp95d},
      {"points4", "point sequence for point-driven 4-axis controllers: X Y U V per line, both planes at the same t",
       PlaneNeed::Both, rowPoints4},
      {"3b", "Chinese fast-wire 3B code: B x B y B J G Z, whole micrometres, one file per plane", PlaneNeed::One,
       rowThreeB},
      {"4b", "4B code: 3B with the radius and convex/concave marks for controls that offset the wire [unsure layout]",
       PlaneNeed::One, rowFourB},
      {"iso", "normalised ISO G-code: absolute, one move per block, I J incremental; --for a machine's conventions",
       PlaneNeed::Both, rowIso},
      {"polar", "polar X/C for mill-turn lathes: X diameter (or radius), C degrees unwrapped, spirals within tolerance",
       PlaneNeed::One, rowPolar},
      {"dxf", "a DXF drawing for CAD: the wire path on LOWER (and UPPER), the programmed contour, passes by layer",
       PlaneNeed::Both, rowDxf},
  };
  return table;
}

const Emitter* findEmitter(std::string_view name) {
  for (const Emitter& e : emitters())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace kerf::converter
