// kerf cam: a drawing's contours into a toolpath (cam.h; docs/cam.md).
#include "kerf/converter/cam/cam.h"

#include "kerf/geometry/intersection.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/chain.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kerf::converter {

using geometry::Segment;
using geometry::Vec2;

namespace {

std::vector<Segment> reversedPath(std::span<const Segment> path) {
  std::vector<Segment> r;
  r.reserve(path.size());
  for (auto it = path.rbegin(); it != path.rend(); ++it) r.push_back(it->reversed());
  return r;
}

/// The loop rotated to begin at element k.
template <class T>
std::vector<T> rotated(const std::vector<T>& loop, std::size_t k) {
  std::vector<T> r(loop.begin() + static_cast<std::ptrdiff_t>(k), loop.end());
  r.insert(r.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(k));
  return r;
}

/// The wire loop rotated (and its nearest piece split) so that it begins at its point nearest p.
std::vector<Segment> loopFrom(const std::vector<geometry::WirePiece>& loop, const Vec2& p, double tol) {
  std::size_t best = 0;
  double bestT = 0, bestD = 1e300;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double t = loop[i].segment.parameterOf(p);
    const double d = (loop[i].segment.pointAt(t) - p).norm();
    if (d < bestD) bestD = d, best = i, bestT = t;
  }
  std::vector<Segment> segs;
  for (const geometry::WirePiece& w : loop) segs.push_back(w.segment);
  const Segment& s = segs[best];
  const double len = s.length();
  if (bestT * len <= tol) return rotated(segs, best);
  if ((1 - bestT) * len <= tol) return rotated(segs, (best + 1) % segs.size());
  const Segment head = geometry::subSegment(s, 0, bestT), tail = geometry::subSegment(s, bestT, 1);
  std::vector<Segment> r{tail};
  for (std::size_t k = 1; k < segs.size(); ++k) r.push_back(segs[(best + k) % segs.size()]);
  r.push_back(head);
  r.back().end = r.front().start;
  return r;
}

Vec2 rightNormal(const Vec2& t) { return {t.y(), -t.x()}; }

}  // namespace

ContourWire offsetContour(std::span<const Segment> contour, double radius, WireSide side) {
  ContourWire w;
  const double area = geometry::signedArea(contour);
  double length = 0.0;
  for (const Segment& s : contour) length += s.length();
  if (std::abs(area) <= 1e-6 * length) {  // no inside and no outside: not a part
    w.degenerate = true;
    return w;
  }
  const bool ccw = area > 0;
  // Outside of a counter-clockwise contour is right of travel (negative).
  w.distance = (side == WireSide::Outside) == ccw ? -radius : radius;
  const geometry::WireOffsetResult r = geometry::wireOffset(contour, w.distance);
  w.loops = r.paths;
  w.lost = r.lost;
  w.refused = r.refused;
  if (r.tooMuchWork) w.tooMuchWork = r.tests - 1;
  return w;
}

void reportContourWire(const ContourWire& wire, std::size_t number, const DrawingResult& drawing,
                       const geometry::Chain& chain, double radius, const SourceFile* source, Diagnostics& diags) {
  auto spanOf = [&](std::size_t k) {
    const DrawingElement& e = drawing.drawing.elements[chain.elements[k]];
    return e.span.length ? e.span : SourceSpan::wholeFile();
  };
  const std::string name = "contour " + std::to_string(number);
  if (wire.degenerate) {
    diags.warning(Code::WirePathSplits, source, spanOf(0),
                  name + " encloses no area: it runs back over itself, so it has no inside or outside to cut",
                  "the drawing may hold the same lines twice; the wire path leaves it out");
    return;
  }
  if (wire.refused) {
    diags.error(Code::WireOffsetRefused, source, spanOf(0),
                wire.tooMuchWork
                    ? "the wire offset of " + name + " needs more than " + std::to_string(wire.tooMuchWork) +
                          " exact tests of pieces whose boxes overlap (long elements side by side, as in a star of "
                          "thin spikes): refused, not computed"
                    : "the wire offset of " + name + " needs more pieces than the budget allows: not computed");
    return;
  }
  for (const geometry::LostRun& run : wire.lost) {
    const std::size_t k = run.first;
    if (run.fillet) {
      diags.note(Code::InsideCornerRadius, source, spanOf(k),
                 "the inside corner of " + name + " at " + formatPoint(run.where) + " has radius " +
                     formatFixed(chain.path[k].radius(), 3) + " mm, smaller than the wire offset " +
                     formatFixed(radius, 3) + " mm: the wire cuts it with radius " + formatFixed(radius, 3) + " mm",
                 formatFixed(run.uncut, 4) + " mm of material stays in the corner");
      continue;
    }
    diags.warning(Code::WireCannotReach, source, spanOf(k),
                  "the wire (offset " + formatFixed(radius, 3) + " mm, " + formatFixed(2 * radius, 3) +
                      " mm wide) cannot reach " + std::to_string(run.count) + " element" + (run.count == 1 ? "" : "s") +
                      " of " + name + " from element " + std::to_string(k + 1) +
                      ": a slot or recess narrower than the wire; up to " + formatFixed(run.uncut, 3) +
                      " mm of material stays at " + formatPoint(run.where),
                  "a smaller wire, or a second operation, cuts it; the wire path leaves it out");
  }
  if (wire.loops.empty()) {
    diags.error(Code::WirePathSplits, source, spanOf(0),
                name + " is smaller than the wire: at an offset of " + formatFixed(radius, 3) +
                    " mm on its inside nothing is left to cut");
  } else if (wire.loops.size() > 1) {
    diags.warning(Code::WirePathSplits, source, spanOf(0),
                  "the wire path of " + name + " splits into " + std::to_string(wire.loops.size()) +
                      " loops: the contour narrows below the wire's width somewhere between them",
                  "each loop is cut on its own");
  }
}

namespace {

/// The contours kerf cam cuts (indices into chains), as --contour and --open-paths choose them;
/// nothing (said) when none can be cut.
std::optional<std::vector<std::size_t>> chooseContours(const std::vector<geometry::Chain>& chains, const CamOptions& o,
                                                       const SourceFile* source, Diagnostics& diags) {
  std::vector<std::size_t> chosen;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (o.contour && *o.contour != c + 1) continue;
    if (!chains[c].closed && !o.openPaths) {
      if (o.contour)
        diags.error(Code::ContourOpen, source, SourceSpan::wholeFile(),
                    "contour " + std::to_string(c + 1) + " does not close: a wire cannot cut it as a part");
      continue;
    }
    chosen.push_back(c);
  }
  if (o.contour && *o.contour > chains.size()) {
    diags.error(Code::OptionDoesNotFit, source, SourceSpan::wholeFile(),
                "--contour " + std::to_string(*o.contour) + ": the drawing has " + std::to_string(chains.size()) +
                    " contour" + (chains.size() == 1 ? "" : "s"));
    return std::nullopt;
  }
  if (chosen.empty()) {
    if (!o.contour)
      diags.error(Code::NothingCut, source, SourceSpan::wholeFile(), "the drawing has no closed contour to cut",
                  chains.empty() ? std::string() : "--open-paths cuts open contours along the drawing");
    return std::nullopt;
  }
  if (o.entry && chosen.size() > 1) {
    diags.error(Code::OptionDoesNotFit, source, SourceSpan::wholeFile(),
                "--entry gives one start hole, but " + std::to_string(chosen.size()) +
                    " contours are cut: choose one with --contour");
    return std::nullopt;
  }
  return chosen;
}

/// The toolpath as it is made (kerf cam's program, and a drawing shown as a toolpath): where the
/// wire is, a rapid to each new start, cuts along paths. A move made from a drawing entity names it
/// (its line and span); kerf cam's moves name none (the program made has its own lines).
struct PathWriter {
  Toolpath& toolpath;
  double cutLength = 0.0;
  bool first = true;
  Vec2 at = Vec2::Zero();

  static Move moveFrom(const Segment& s, MoveKind kind, const DrawingElement* from) {
    Move m;
    m.kind = kind;
    m.lower = s;
    if (from) {
      m.line = from->where;
      m.span = from->span;
    }
    return m;
  }

  /// A rapid from where the wire is to p (the first path starts there).
  void travelTo(const Vec2& p, const DrawingElement* from = nullptr) {
    if (first) {
      toolpath.start = p;
      first = false;
    } else if ((p - at).norm() > 1e-12) {
      toolpath.moves.push_back(moveFrom(Segment::line(at, p), MoveKind::Rapid, from));
    }
    at = p;
  }

  /// Cuts along s; returns its length.
  double cut(const Segment& s, WireOffset code, const DrawingElement* from = nullptr) {
    Move m = moveFrom(s, s.isArc() ? MoveKind::Arc : MoveKind::Line, from);
    m.wireOffset = code;
    toolpath.moves.push_back(m);
    at = s.end;
    cutLength += s.length();
    return s.length();
  }

  /// Cuts along the segments; returns their length.
  double cut(std::span<const Segment> path, WireOffset code) {
    double length = 0.0;
    for (const Segment& s : path) length += cut(s, code);
    return length;
  }
};

/// --open-paths: an open contour cut as drawn, from its first end, the wire centre on the line.
void cutOpen(PathWriter& w, CamContour& info, const std::vector<Segment>& contour, const DrawingElement& first,
             const CamOptions& o, const SourceFile* source, Diagnostics& diags) {
  info.open = true;
  for (const Segment& s : contour) info.contourLength += s.length();
  if (o.offset > 0 && !o.controllerOffset) {
    diags.warning(Code::ContourOpen, source, first.span.length ? first.span : SourceSpan::wholeFile(),
                  "contour " + std::to_string(info.number) +
                      " is open: cut along it as drawn, the wire centre on the line, without the offset",
                  "an open contour has no inside or outside; close it to cut a part");
  }
  w.travelTo(contour.front().start);
  info.wireLength += w.cut(contour, WireOffset::Off);
}

/// Where the lead-in to a loop starts, leadIn mm out along n from the loop's first point; where
/// the scrap is narrower than the lead-in (a small hole), halfway to the loop's other side.
Vec2 leadInStart(const std::vector<Segment>& loop, const Vec2& n, double leadIn) {
  const Vec2 begin = loop.front().start;
  double leadLength = leadIn;
  if (leadLength > 0) {
    const Segment ray = Segment::line(begin + 1e-6 * n, begin + (2 * leadLength + 1e-6) * n);
    double nearest = 2 * leadLength;
    for (const Segment& s : loop) {
      const geometry::SegmentIntersection x = geometry::intersect(ray, s, 1e-9);
      for (int k = 0; k < x.count; ++k) nearest = std::min(nearest, (x.points[k] - begin).norm());
    }
    leadLength = std::min(leadLength, 0.5 * nearest);
  }
  return begin + leadLength * n;
}

/// A closed contour: oriented, started at the vertex asked for, its wire path (here or by the
/// controller), each loop entered by a lead-in from its start hole.
void cutClosed(PathWriter& w, CamContour& info, std::vector<Segment> contour, const geometry::Chain& chain,
               const DrawingResult& drawing, const CamOptions& o, const SourceFile* source, Diagnostics& diags) {
  // Orientation: the wire right of travel unless asked for the left; outside that is counter-clockwise.
  const bool left = o.wireOnLeft.value_or(false);
  const bool wantCcw = (info.side == WireSide::Outside) != left;
  if ((geometry::signedArea(contour) > 0) != wantCcw) contour = reversedPath(contour);
  info.area = std::abs(geometry::signedArea(contour));
  for (const Segment& s : contour) info.contourLength += s.length();
  // Start: the vertex nearest the point asked for (or the start hole).
  const std::optional<Vec2> near = o.start ? o.start : o.entry;
  if (near) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < contour.size(); ++k)
      if ((contour[k].start - *near).norm() < (contour[best].start - *near).norm()) best = k;
    contour = rotated(contour, best);
  }
  const Vec2 startVertex = contour.front().start;
  // The wire path.
  std::vector<std::vector<Segment>> loops;
  if (o.controllerOffset || o.offset <= 0) {
    loops.push_back(contour);
  } else {
    const ContourWire wire = offsetContour(contour, o.offset, info.side);
    reportContourWire(wire, info.number, drawing, chain, o.offset, source, diags);
    for (const auto& loop : wire.loops) loops.push_back(loopFrom(loop, startVertex, o.tolerance));
  }
  // The start hole: given, or lead-in mm out from the start vertex on the wire's side.
  const Vec2 tIn = contour.back().tangentAt(1), tOut = contour.front().tangentAt(0);
  Vec2 n = rightNormal(tIn) + rightNormal(tOut);
  if (left) n = -n;
  if (n.norm() < 1e-9) n = left ? -rightNormal(tOut) : rightNormal(tOut);
  n.normalize();
  const WireOffset offsetCode = !o.controllerOffset ? WireOffset::Off : left ? WireOffset::Left : WireOffset::Right;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::vector<Segment>& loop = loops[l];
    const Vec2 begin = loop.front().start;
    const Vec2 entry = o.entry && l == 0 ? *o.entry : leadInStart(loop, n, o.leadIn);
    w.travelTo(entry);
    if ((begin - entry).norm() > 1e-12) {
      const Segment lead = Segment::line(entry, begin);
      w.cut(std::span<const Segment>(&lead, 1), offsetCode);
    }
    info.wireLength += w.cut(loop, offsetCode);
  }
}

}  // namespace

std::optional<CamResult> makeProgram(const DrawingResult& drawing, const SourceFile* source, const CamOptions& o,
                                     Diagnostics& diags) {
  const std::vector<geometry::Chain>& chains = drawing.contours;
  std::optional<std::vector<std::size_t>> chosen = chooseContours(chains, o, source, diags);
  if (!chosen) return std::nullopt;
  // The chosen contours shifted; how deep each sits inside the others is drawing.depth.
  std::vector<std::vector<Segment>> paths(chains.size());
  for (std::size_t c : *chosen) {
    for (Segment s : chains[c].path) {
      s.start += o.shift;
      s.end += o.shift;
      s.centre += o.shift;
      paths[c].push_back(s);
    }
  }
  const std::vector<int>& depth = drawing.depth;
  *chosen = cuttingOrder(drawing, std::move(*chosen));

  CamResult result;
  result.toolpath.format = InputFormat::Iso;
  PathWriter w{result.toolpath};
  for (std::size_t c : *chosen) {
    CamContour info;
    info.number = c + 1;
    info.depth = depth[c];
    info.side = sideAtDepth(o.side, depth[c]);
    info.elements = paths[c].size();
    if (chains[c].closed)
      cutClosed(w, info, paths[c], chains[c], drawing, o, source, diags);
    else
      cutOpen(w, info, paths[c], drawing.drawing.elements[chains[c].elements.front()], o, source, diags);
    result.contours.push_back(info);
  }
  result.cutLength = w.cutLength;
  result.toolpath.endedProperly = true;
  result.toolpath.blocks = result.toolpath.moves.size();
  return result;
}

std::vector<std::size_t> cuttingOrder(const DrawingResult& drawing, std::vector<std::size_t> chosen) {
  const std::vector<int>& depth = drawing.depth;
  std::stable_sort(chosen.begin(), chosen.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  return chosen;
}

std::vector<ContourWire> drawingWires(const DrawingResult& drawing, double radius, WireSide side,
                                      const SourceFile* source, Diagnostics& diags) {
  std::vector<ContourWire> wires(drawing.contours.size());
  for (std::size_t c = 0; c < drawing.contours.size(); ++c) {
    const geometry::Chain& chain = drawing.contours[c];
    if (!chain.closed) continue;
    wires[c] = offsetContour(chain.path, radius, sideAtDepth(side, drawing.depth[c]));
    reportContourWire(wires[c], c + 1, drawing, chain, radius, source, diags);
  }
  return wires;
}

Toolpath drawingToolpath(const DrawingResult& drawing, const std::vector<ContourWire>* wires) {
  Toolpath path;
  PathWriter w{path};
  std::vector<std::size_t> all(drawing.contours.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  for (const std::size_t ci : cuttingOrder(drawing, std::move(all))) {
    const geometry::Chain& c = drawing.contours[ci];
    const auto element = [&](std::size_t k) { return &drawing.drawing.elements[c.elements[k]]; };
    if (wires && c.closed && ci < wires->size()) {  // the wire path instead of the contour
      for (const auto& loop : (*wires)[ci].loops) {
        if (loop.empty()) continue;
        w.travelTo(loop.front().segment.start, element(0));
        for (const geometry::WirePiece& piece : loop) w.cut(piece.segment, WireOffset::Off, element(piece.element));
      }
      continue;
    }
    w.travelTo(c.path.front().start, element(0));
    for (std::size_t k = 0; k < c.elements.size(); ++k) w.cut(c.path[k], WireOffset::Off, element(k));
  }
  path.endedProperly = true;
  return path;
}

}  // namespace kerf::converter
