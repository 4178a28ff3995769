// The emitter table, and the point-file emitters (points/points.cpp) in its shape.
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/nc/number_format.h"

namespace kerf::converter {

namespace {

/// pairs: points4 (an X Y U V pair a line, in the profile's number format).
EmitOutput fromPoints(PointOutput&& p, const EmitRequest& request, bool pairs = false) {
  EmitOutput out;
  out.text = std::move(p.text);
  out.what = pairs ? std::to_string(p.points) + " point pairs (points4: X Y U V, numbers as the " +
                         request.profile.name + " profile writes them)"
                   : std::to_string(p.points) + " points (" + request.profile.name + " profile)";
  const std::size_t capacity = request.maxPoints ? *request.maxPoints : request.profile.maxPoints.value_or(0);
  out.detail = std::string("; ") + (p.sampling.mode == geometry::SamplingMode::Step ? "step k = " : "tolerance ") +
               formatFixed(p.sampling.value, 6) + " mm" +
               (p.fitted ? " chosen to fit " + std::to_string(capacity) + " points" : "") + ", max deviation " +
               formatFixed(p.stats.maxDeviation, 6) + " mm";
  return out;
}

PointRequest pointRequest(const EmitRequest& r) {
  PointRequest p;
  p.sampling = r.sampling;
  p.maxPoints = r.maxPoints;
  p.startLine = r.startLine;
  p.atGuides = r.atGuides;
  return p;
}

}  // namespace

std::optional<EmitOutput> writeBp95d(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                     Diagnostics& diags) {
  std::optional<PointOutput> p = emitPoints(toolpath, source, request.profile, pointRequest(request), diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request);
}

std::optional<EmitOutput> writePoints4(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                       Diagnostics& diags) {
  std::optional<PointOutput> p =
      emitPoints4(toolpath, source, request.profile, pointRequest(request), request.relativeUv, diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request, true);
}

bool startCutPathAt(const Toolpath& toolpath, CutPath& path, std::uint32_t startLine, const SourceFile* source,
                    Diagnostics& diags) {
  std::size_t k = 0;
  while (k < path.segments.size() && toolpath.moves[path.moveIndex[k]].line != startLine) ++k;
  if (k == path.segments.size()) {
    diags.error(Code::StartBlockNotFound, source, SourceSpan::wholeFile(),
                "no cutting move comes from line " + std::to_string(startLine));
    return false;
  }
  const auto at = static_cast<std::ptrdiff_t>(k);
  const bool closed = (path.segments.back().end - path.segments.front().start).norm() <= 1e-6;
  if (closed) {
    std::rotate(path.segments.begin(), path.segments.begin() + at, path.segments.end());
    std::rotate(path.moveIndex.begin(), path.moveIndex.begin() + at, path.moveIndex.end());
  } else if (k > 0) {
    diags.warning(Code::StartBlockNotFound, source, toolpath.moves[path.moveIndex[k]].span,
                  "the cut path is open: the " + std::to_string(k) + " cutting moves before this one are left out");
    path.segments.erase(path.segments.begin(), path.segments.begin() + at);
    path.moveIndex.erase(path.moveIndex.begin(), path.moveIndex.begin() + at);
  }
  return true;
}

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
  out.feeds = toolpath.feeds;  // the moves keep their feeds
  if (!toolpath.isTaper()) {
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
    for (const geometry::Segment& piece : pieces) {
      Move m = toolpath.moves[i];
      m.lower = piece;
      if (m.kind != MoveKind::Rapid) m.kind = piece.isArc() ? MoveKind::Arc : MoveKind::Line;
      out.moves.push_back(m);
    }
  }
  return out;
}

const std::vector<Emitter>& emitters() {
  static const std::vector<Emitter> table = {
      {"bp95d", "point sequence for point-driven 2-axis controllers (BP-95d): X Y per line, profile-driven",
       PlaneNeed::One, writeBp95d},
      {"points4", "point sequence for point-driven 4-axis controllers: X Y U V per line, both planes at the same t",
       PlaneNeed::Both, writePoints4},
      {"3b", "Chinese fast-wire 3B code: B x B y B J G Z, whole micrometres, one file per plane", PlaneNeed::One,
       writeThreeB},
      {"4b", "4B code: 3B with the radius and convex/concave marks for controls that offset the wire [unsure layout]",
       PlaneNeed::One, writeFourB},
      {"iso", "normalised ISO G-code: absolute, one move per block, I J incremental; --for a machine's conventions",
       PlaneNeed::Both, writeIso},
      {"polar", "polar X/C for mill-turn lathes: X diameter (or radius), C degrees unwrapped, spirals within tolerance",
       PlaneNeed::One, writePolar},
  };
  return table;
}

const Emitter* findEmitter(std::string_view name) {
  for (const Emitter& e : emitters())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace kerf::converter
