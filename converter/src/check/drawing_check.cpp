// A program against its drawing (drawing_check.h): the part edge, per drawing element the largest
// deviation both ways, where the part was placed.
// Sections: 1. the part edge  2. findings  3. measures and placement  4. the comparison
#include "kerf/converter/check/drawing_check.h"

#include "finding.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/align.h"
#include "kerf/geometry/chain.h"
#include "kerf/geometry/deviation.h"
#include "kerf/geometry/offset.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace kerf::converter {

namespace {

/// mm: ends of moved elements this close meet where they are (a written program's resolution).
constexpr double kJoinTolerance = 0.002;
/// A moved element's corner lies at most this many offsets from it (a corner of 1.1°); farther,
/// the corner is taken as lost to rounding, not drawn.
constexpr double kFarthestCorner = 100.0;

/// One run of the part edge: a contour's last pass that is not a cut-off, or one of its cut-offs;
/// its moves along the contour, in order.
struct EdgeRun {
  std::vector<std::size_t> moves;
  const Pass* pass = nullptr;
  std::size_t contour = 0;  ///< in Structure::contours
  bool upper = false;       ///< the moves' upper contour (DrawingCheckOptions::upperPlane)
};

// ---- 1. the part edge ---------------------------------------------------------------------------

/// The runs of the part edge (see the header). A move is in one run at most.
std::vector<EdgeRun> edgeRuns(const Toolpath& tp, const Structure& structure, bool upper) {
  std::vector<EdgeRun> runs;
  std::set<std::size_t> taken;
  for (std::size_t c = 0; c < structure.contours.size(); ++c) {
    const Contour& contour = structure.contours[c];
    const Pass* last = nullptr;
    for (const Pass& p : contour.passes)
      if (!p.cutOff) last = &p;
    for (const Pass& p : contour.passes) {
      if (&p != last && !p.cutOff) continue;
      EdgeRun run{{}, &p, c, upper};
      for (std::size_t i = p.alongFirst; i < p.alongEnd && i < tp.moves.size(); ++i)
        if (tp.moves[i].isCut() && taken.insert(i).second) run.moves.push_back(i);
      if (!run.moves.empty()) runs.push_back(std::move(run));
    }
  }
  return runs;
}

/// Move i of the part edge: on the lower plane as programmed (the contour the program wrote where
/// a wire offset was applied), or its upper contour (a taper program's upper plane).
geometry::Segment programmedOf(const Toolpath& tp, std::size_t i, bool upper) {
  if (upper) return tp.upperOf(i);
  return i < tp.programmed.size() ? tp.programmed[i] : tp.moves[i].lower;
}

/// A pass cut with no G41/G42 in force: its moves are the wire's centre.
bool isWireCentre(const EdgeRun& run) { return run.pass->side == WireOffset::Off; }

/// A run's moves as programmed (programmedOf), in order.
std::vector<geometry::Segment> programmedRun(const Toolpath& tp, const EdgeRun& run) {
  std::vector<geometry::Segment> path;
  for (const std::size_t i : run.moves) path.push_back(programmedOf(tp, i, run.upper));
  return path;
}

/// Is element k of the path the wire rolling round a corner of the part: an arc of the offset's
/// radius about that corner, which moving back by d collapses into its centre?
bool isCornerArc(const std::vector<geometry::Segment>& path, std::size_t k, double d) {
  const geometry::Segment& s = path[k];
  return s.isArc() && std::abs(s.radius() - std::abs(d)) <= kJoinTolerance &&
         !geometry::offsetSegment(s, d * (1 + 1e-9));
}

/// A wire path's corner arcs, moved back by d, become their centres: the corner a wire rolls round
/// is its arc's centre as written, where the neighbours' extensions meet wherever the program's
/// rounding turned them (and far away when they are nearly in line). The moved lines next to such
/// an arc are made to end at its centre; the arc itself leaves no piece.
void cornersAtCentres(const std::vector<geometry::Segment>& path, double d, bool closed,
                      std::vector<geometry::Segment>& moved, std::vector<bool>& corner) {
  const std::size_t n = path.size();
  corner.assign(n, false);
  for (std::size_t k = 0; k < n; ++k) corner[k] = isCornerArc(path, k, d);
  for (std::size_t k = 0; k < n; ++k) {
    if (!corner[k]) continue;
    const std::size_t before = k > 0 ? k - 1 : closed ? n - 1 : SIZE_MAX;
    const std::size_t after = k + 1 < n ? k + 1 : closed ? 0 : SIZE_MAX;
    if (before != SIZE_MAX && !moved[before].isArc())
      moved[before] = geometry::Segment::line(moved[before].start, path[k].centre);
    if (after != SIZE_MAX && !moved[after].isArc())
      moved[after] = geometry::Segment::line(path[k].centre, moved[after].end);
  }
}

/// The pieces of a run's path moved by d (> 0: left of travel), each with the move it comes from.
/// The corners are sharp (geometry/offset.h offsetChain), as the contour a G41/G42 program writes:
/// a wire path's arcs round the part's corners shrink back to those corners.
std::vector<EdgeDeviation> movedPieces(const Toolpath& tp, const EdgeRun& run, double d) {
  const bool closed = run.pass->closes && !run.pass->cutOff;
  const std::vector<geometry::Segment> path = programmedRun(tp, run);
  const std::vector<double> distances(path.size(), d);
  geometry::OffsetChainOptions o;
  o.closed = closed;
  // Ends this close already meet: a program's rounding (3B's whole micrometres) turns a tangent
  // joint by a little, and the extended elements would meet far away.
  o.tolerance = kJoinTolerance;
  geometry::OffsetChainResult r = geometry::offsetChain(path, distances, o);
  std::vector<bool> corner;
  cornersAtCentres(path, d, closed, r.segments, corner);
  std::vector<EdgeDeviation> pieces;
  for (std::size_t k = 0; k < r.segments.size() && k < run.moves.size(); ++k) {
    if (corner[k]) continue;
    geometry::Segment piece = r.segments[k];
    // A joint between elements that are nearly tangent, or round a corner arc of a micrometre,
    // can put the sharp corner far away: past kFarthestCorner offsets from the element, the
    // element is moved alone, without its corners.
    const double far = kFarthestCorner * std::abs(d) + path[k].length();
    if ((piece.start - path[k].start).norm() > far || (piece.end - path[k].end).norm() > far) {
      const std::optional<geometry::Segment> alone = geometry::offsetSegment(path[k], d);
      if (!alone) continue;  // an arc the offset collapses: a corner, which its neighbours give
      piece = *alone;
    }
    if (piece.length() > 1e-9) pieces.push_back({run.moves[k], piece});
  }
  return pieces;
}

/// The largest distance from the pieces to the drawing (infinite when there are none).
double farthestOf(const std::vector<EdgeDeviation>& pieces, const geometry::DeviationSet& drawn, double precision) {
  double worst = pieces.empty() ? std::numeric_limits<double>::infinity() : 0.0;
  for (const EdgeDeviation& p : pieces)
    worst = std::max(worst, geometry::farthestFrom(p.segment, drawn, precision).distance);
  return worst;
}

/// The drawing's chains (contours), for each element its chain, and their nesting (as kerf cam
/// nests them to choose each contour's side).
struct DrawnChains {
  std::vector<geometry::Chain> chains;
  std::vector<std::size_t> chainOf;
  std::vector<int> depth;  ///< per chain: how many closed chains wind round it (0: outermost or open)
};

DrawnChains chainDrawing(const std::vector<geometry::Segment>& drawn) {
  DrawnChains out;
  out.chains = geometry::chainSegments(drawn, {});
  out.chainOf.assign(drawn.size(), SIZE_MAX);
  for (std::size_t c = 0; c < out.chains.size(); ++c)
    for (const std::size_t k : out.chains[c].elements) out.chainOf[k] = c;
  out.depth = geometry::nestingDepths(out.chains);
  return out;
}

/// How the wire-centre runs were taken, for the note (K0633).
struct MovedBack {
  std::size_t asWritten = 0, moved = 0, chosen = 0;
};

/// The part edge: every run's pieces, the wire-centre runs moved back by the wire offset when it
/// is given (see DrawingCheckOptions::wireOutside for the side). A cut-off moves as its contour's
/// pass does: it runs the same way along the same contour.
std::vector<EdgeDeviation> partEdge(const Toolpath& tp, const std::vector<EdgeRun>& runs,
                                    const DrawingCheckOptions& options, const geometry::DeviationSet& drawn,
                                    const DrawnChains& dc, MovedBack& said) {
  std::map<std::size_t, double> movedBy;  // contour -> the distance its pass moved by
  std::vector<EdgeDeviation> edge;
  std::vector<std::size_t> ordered(runs.size());  // passes first, then cut-offs (they take their pass's side)
  for (std::size_t r = 0; r < runs.size(); ++r) ordered[r] = r;
  std::stable_partition(ordered.begin(), ordered.end(), [&](std::size_t r) { return !runs[r].pass->cutOff; });
  for (const std::size_t r : ordered) {
    const EdgeRun& run = runs[r];
    const int direction = run.pass->direction;
    const auto known = movedBy.find(run.contour);
    if (!isWireCentre(run) || !options.wireOffset || *options.wireOffset <= 0 ||
        (direction == 0 && known == movedBy.end())) {
      if (isWireCentre(run)) ++said.asWritten;
      for (const std::size_t i : run.moves) edge.push_back({i, programmedOf(tp, i, run.upper)});
      continue;
    }
    const double radius = *options.wireOffset;
    double d = 0.0;
    if (known != movedBy.end()) {
      d = known->second;
    } else if (options.wireOutside) {
      // The wire outside the part: the part lies inside the wire's loop, left of a
      // counter-clockwise one. Nesting turns the side over: the nesting of the drawing contour
      // the run follows (the one nearest its first move), as kerf cam chose the side from it.
      const geometry::Vec2 probe = programmedOf(tp, run.moves.front(), run.upper).pointAt(0.5);
      const std::size_t element = drawn.empty() ? SIZE_MAX : drawn.chord(drawn.nearest(probe).chord).owner;
      const std::size_t chain = element < dc.chainOf.size() ? dc.chainOf[element] : SIZE_MAX;
      const int depth = chain < dc.depth.size() ? dc.depth[chain] : 0;
      const bool partInside = (depth % 2 == 0) == *options.wireOutside;
      d = (partInside ? 1.0 : -1.0) * direction * radius;
    } else {
      const double left = farthestOf(movedPieces(tp, run, radius), drawn, options.precision);
      const double right = farthestOf(movedPieces(tp, run, -radius), drawn, options.precision);
      d = left <= right ? radius : -radius;
      ++said.chosen;
    }
    movedBy[run.contour] = d;
    ++said.moved;
    const std::vector<EdgeDeviation> pieces = movedPieces(tp, run, d);
    edge.insert(edge.end(), pieces.begin(), pieces.end());
  }
  return edge;
}

// ---- 2. findings --------------------------------------------------------------------------------

/// "LINE", "ARC", "arc of an LWPOLYLINE".
std::string elementName(const DrawnElement& e) {
  if (e.entity == "LINE" || e.entity == "ARC" || e.entity == "CIRCLE") return e.entity;
  return std::string(e.segment.isArc() ? "arc" : "line") + (e.entity.empty() ? "" : " of the " + e.entity);
}

std::string um(double mm) { return formatFixed(mm * 1000.0, 1) + " µm"; }

/// K0631: the drawing's closed contours that no contour of the program follows — no piece of the
/// edge has an element of theirs as its nearest (a hole left out: its elements are nearest to the
/// outline's moves, but those are nearer the outline). Their elements are said once, as the contour.
std::set<std::size_t> reportUncut(const std::vector<DrawnElement>& drawing, const DrawnChains& dc,
                                  const std::vector<std::size_t>& nearestOfPiece, const SourceFile* drawingSource,
                                  Diagnostics& diags) {
  std::vector<bool> followed(dc.chains.size(), false);
  for (const std::size_t k : nearestOfPiece)
    if (k < dc.chainOf.size() && dc.chainOf[k] != SIZE_MAX) followed[dc.chainOf[k]] = true;
  std::set<std::size_t> said;
  for (std::size_t c = 0; c < dc.chains.size(); ++c) {
    const geometry::Chain& chain = dc.chains[c];
    if (!chain.closed || followed[c]) continue;
    geometry::Box box;
    for (const geometry::Segment& s : chain.path) box.add(s.bounds());
    const DrawnElement& first = drawing[chain.elements.front()];
    const geometry::Vec2 centre = 0.5 * (box.min + box.max);
    diags.error(Code::DrawingContourNotCut, drawingSource, first.span,
                "the drawing's contour around " + formatPoint(centre) + " (" + std::to_string(chain.elements.size()) +
                    (chain.elements.size() == 1 ? " element" : " elements") +
                    ") is not cut: no contour of the program follows it",
                "a hole or an outline the program forgot, or a drawing placed elsewhere (--drawing-origin)");
    said.insert(chain.elements.begin(), chain.elements.end());
  }
  return said;
}

/// The finding for the elements of one drawing contour that are out of tolerance. When every
/// element of a closed contour is off by one distance (within the tolerance), the contour is said
/// once: the cut is the contour moved sideways, an offset applied twice or not taken back.
void reportOff(const std::vector<const ElementDeviation*>& off, std::size_t elementsInChain, bool closed,
               const Toolpath& tp, const std::vector<DrawnElement>& drawing, const DrawingCheckOptions& options,
               const SourceFile* program, const SourceFile* drawingSource, Diagnostics& diags) {
  const std::string dxf = drawingSource ? drawingSource->name() : "drawing";
  double least = off.front()->deviation, most = least;
  for (const ElementDeviation* e : off) {
    least = std::min(least, e->deviation);
    most = std::max(most, e->deviation);
  }
  if (closed && off.size() == elementsInChain && elementsInChain > 1 && most - least <= options.tolerance) {
    const ElementDeviation& e =
        **std::max_element(off.begin(), off.end(), [](auto* a, auto* b) { return a->deviation < b->deviation; });
    diags.report(
        finding(Severity::Error, Code::DrawingElementOff, program, tp.moves[e.move], e.move, {e.at.x(), e.at.y(), 0.0},
                "every element of the drawing's contour through " + dxf + " line " +
                    std::to_string(drawing[e.element].line) + " (" + std::to_string(off.size()) + " elements) is cut " +
                    um(least) + " to " + um(most) + " off: the cut is the contour moved sideways by one distance",
                "an offset applied twice (G41/G42 on a path that is already the wire's centre), or a wire-centre path "
                "compared without --offset"));
    return;
  }
  for (const ElementDeviation* e : off) {
    const DrawnElement& d = drawing[e->element];
    diags.report(finding(
        Severity::Error, Code::DrawingElementOff, program, tp.moves[e->move], e->move, {e->at.x(), e->at.y(), 0.0},
        "the drawing's " + elementName(d) + " (" + dxf + " line " + std::to_string(d.line) + ") is cut " +
            um(e->deviation) + " off at " + formatPoint(e->at) + ", more than the tolerance " + um(options.tolerance) +
            ": this block is the nearest",
        "a radius or a coordinate typed wrong, or an offset applied twice; --drawing-tolerance sets the tolerance"));
  }
}

/// K0632: pieces of the edge that cut farther than the tolerance from every element, one finding
/// per run of them.
void reportExtraCuts(const DrawingComparison& out, const Toolpath& tp, double tolerance, const SourceFile* program,
                     Diagnostics& diags) {
  for (std::size_t j = 0; j < out.edge.size();) {
    if (out.edge[j].deviation <= tolerance) {
      ++j;
      continue;
    }
    std::size_t k = j;
    double worst = 0.0;
    std::set<std::size_t> moves;
    while (k < out.edge.size() && out.edge[k].deviation > tolerance) {
      moves.insert(out.edge[k].move);
      worst = std::max(worst, out.edge[k++].deviation);
    }
    const EdgeDeviation& e = out.edge[j];
    diags.report(finding(Severity::Warning, Code::CutNotInDrawing, program, tp.moves[e.move], e.move,
                         {e.at.x(), e.at.y(), 0.0},
                         std::to_string(moves.size()) + (moves.size() == 1 ? " move cuts" : " moves cut") + " up to " +
                             um(worst) + " from every element of the drawing, from " + formatPoint(e.at)));
    j = k;
  }
}

/// K0633: how the passes cut with no wire offset in force were taken.
void reportWireCentre(const MovedBack& said, const DrawingCheckOptions& options, const SourceFile* program,
                      Diagnostics& diags) {
  const std::string plane = options.upperPlane ? " (upper plane)" : "";
  auto passes = [&](std::size_t n) { return std::to_string(n) + (n == 1 ? " pass" : " passes") + plane; };
  if (said.moved > 0)
    diags.note(Code::DrawingWireCentre, program, SourceSpan::wholeFile(),
               "the part edge of " + passes(said.moved) +
                   " cut with no G41/G42 in force is the wire's path moved back by " +
                   formatFixed(*options.wireOffset, 4) + " mm" +
                   (said.chosen > 0 ? " to the side that lies nearer the drawing (" + passes(said.chosen) + ")" : ""),
               said.chosen > 0 ? "--side outside (a punch) or inside (a die) says the side" : "");
  if (said.asWritten > 0)
    diags.note(Code::DrawingWireCentre, program, SourceSpan::wholeFile(),
               passes(said.asWritten) + " cut with no G41/G42 in force " + (said.asWritten == 1 ? "is" : "are") +
                   " compared as written: the wire's path, so the deviation includes the wire offset",
               "give --offset (the wire radius plus the spark gap) to move it back to the part edge");
}

/// The comparison at one placement of the drawing, before anything is reported.
struct Measured {
  DrawingComparison out;
  DrawnChains dc;
  std::vector<std::size_t> nearestOfPiece;  ///< per piece of the edge: its nearest drawing element
  MovedBack said;
};

// ---- 3. measures and placement ------------------------------------------------------------------

Measured measure(const Toolpath& tp, const std::vector<EdgeRun>& runs, const std::vector<DrawnElement>& drawing,
                 const std::vector<geometry::Segment>& drawn, const DrawingCheckOptions& options,
                 const SourceFile* drawingSource) {
  Measured m;
  m.out.drawing = drawingSource ? drawingSource->name() : std::string();
  m.out.tolerance = options.tolerance;
  m.out.drawn = drawn;
  const geometry::DeviationSet drawnSet(drawn);
  m.dc = chainDrawing(drawn);
  m.out.edge = partEdge(tp, runs, options, drawnSet, m.dc, m.said);
  std::vector<geometry::Segment> edge;
  for (const EdgeDeviation& e : m.out.edge) edge.push_back(e.segment);
  const geometry::DeviationSet edgeSet(edge);
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const geometry::Farthest f = geometry::farthestFrom(drawn[k], edgeSet, options.precision);
    const std::size_t move = m.out.edge.empty() ? 0 : m.out.edge[f.nearest].move;
    m.out.elements.push_back(
        {k, f.distance, f.at, move, drawing[k].line, m.out.edge.empty() ? 0 : tp.moves[move].line});
    m.out.worst = std::max(m.out.worst, f.distance);
    if (f.distance > options.tolerance) ++m.out.outOfTolerance;
  }
  for (EdgeDeviation& e : m.out.edge) {
    const geometry::Farthest f = geometry::farthestFrom(e.segment, drawnSet, options.precision);
    e.deviation = f.distance;
    e.at = f.at;
    m.nearestOfPiece.push_back(f.nearest);
    m.out.worst = std::max(m.out.worst, f.distance);
  }
  return m;
}

std::vector<geometry::Segment> placed(const std::vector<geometry::Segment>& drawn, const geometry::Placement& p) {
  std::vector<geometry::Segment> out;
  out.reserve(drawn.size());
  for (const geometry::Segment& s : drawn) out.push_back(p.apply(s));
  return out;
}

/// "mirrored left to right (x -> -x), turned 90.000°, shifted by (10.000, 0.000) mm".
std::string describePlacement(const geometry::Placement& p) {
  std::vector<std::string> parts;
  double degrees = p.angle * geometry::kDegreesPerRadian;
  if (p.mirror && std::abs(std::abs(degrees) - 180.0) < 1e-6) {
    parts.push_back("mirrored top to bottom (y -> -y)");
    degrees = 0.0;
  } else if (p.mirror) {
    parts.push_back("mirrored left to right (x -> -x)");
  }
  if (std::abs(degrees) >= 0.5e-4) parts.push_back("turned " + formatFixed(degrees, 4) + "°");
  if (p.shift.norm() >= 0.5e-4) parts.push_back("shifted by " + formatPoint(p.shift, 4) + " mm");
  std::string text;
  for (std::size_t k = 0; k < parts.size(); ++k)
    text += (k == 0 ? "" : k + 1 == parts.size() ? " and " : ", ") + parts[k];
  return text.empty() ? "as placed" : text;
}

/// Is the placement the drawing as it was placed (within what the search can tell)?
bool asPlaced(const geometry::Placement& p, double tolerance) {
  return !p.mirror && std::abs(p.angle) < 1e-7 && p.shift.norm() < 0.1 * tolerance;
}

// ---- 4. the comparison --------------------------------------------------------------------------

/// The findings of one comparison element by element: K0631, K0630, K0632.
void reportAll(const Measured& m, const std::vector<DrawnElement>& drawing, const Toolpath& tp,
               const DrawingCheckOptions& options, const SourceFile* program, const SourceFile* drawingSource,
               Diagnostics& diags) {
  const DrawnChains& dc = m.dc;
  const std::set<std::size_t> uncut = reportUncut(drawing, dc, m.nearestOfPiece, drawingSource, diags);
  std::map<std::size_t, std::vector<const ElementDeviation*>> offByChain;
  for (const ElementDeviation& e : m.out.elements)
    if (e.deviation > options.tolerance && !uncut.count(e.element) && !m.out.edge.empty())
      offByChain[dc.chainOf[e.element]].push_back(&e);
  for (const auto& [c, off] : offByChain) {
    const bool known = c < dc.chains.size();
    reportOff(off, known ? dc.chains[c].elements.size() : 0, known && dc.chains[c].closed, tp, drawing, options,
              program, drawingSource, diags);
  }
  reportExtraCuts(m.out, tp, options.tolerance, program, diags);
}

/// The first move of the part edge, where a finding about the whole part stands.
Diagnostic wholePartFinding(Severity severity, Code code, const Measured& m, const Toolpath& tp,
                            const SourceFile* program, std::string message, std::string help) {
  const std::size_t move = m.out.edge.empty() ? 0 : m.out.edge.front().move;
  Diagnostic d = finding(severity, code, program, tp.moves[move], move, {0.0, 0.0, 0.0}, std::move(message));
  d.help = std::move(help);
  return d;
}

}  // namespace

DrawingComparison compareWithDrawing(const Toolpath& tp, const Structure& structure,
                                     const std::vector<DrawnElement>& drawing, const DrawingCheckOptions& options,
                                     const SourceFile* program, const SourceFile* drawingSource, Diagnostics& diags) {
  std::vector<geometry::Segment> drawn;
  for (const DrawnElement& e : drawing)
    drawn.push_back(geometry::Placement{false, 0.0, -options.origin}.apply(e.segment));
  const std::vector<EdgeRun> runs = edgeRuns(tp, structure, options.upperPlane && tp.isTaper());
  Measured m = measure(tp, runs, drawing, drawn, options, drawingSource);
  reportWireCentre(m.said, options, program, diags);
  // Another placement: asked for (--align), or looked for when the drawing does not fit as placed.
  if ((options.align || m.out.outOfTolerance > 0) && !m.out.edge.empty() && !tp.moves.empty()) {
    std::vector<geometry::Segment> edge;
    for (const EdgeDeviation& e : m.out.edge) edge.push_back(e.segment);
    const geometry::Alignment a = geometry::align(drawn, edge);
    if (std::isfinite(a.rms) && !asPlaced(a.placement, options.tolerance)) {
      Measured there = measure(tp, runs, drawing, placed(drawn, a.placement), options, drawingSource);
      const std::string how = describePlacement(a.placement);
      double elementsWorst = 0.0;
      for (const ElementDeviation& e : there.out.elements) elementsWorst = std::max(elementsWorst, e.deviation);
      const std::string fit = "placed so, its elements lie within " + um(elementsWorst) + " of the part edge";
      if (options.align) {
        m = std::move(there);
        m.out.placement = a.placement;
        diags.report(
            wholePartFinding(a.placement.mirror ? Severity::Error : Severity::Note, Code::DrawingPlacedOtherwise, m, tp,
                             program, "--align: the program cuts the drawing " + how + "; " + fit,
                             a.placement.mirror ? "a mirrored part is another part: mirror the program back" : ""));
      } else if (there.out.outOfTolerance == 0) {
        // The placement explains every element: it is said once, and the deviations stay as placed.
        m.out.placement = a.placement;
        diags.report(wholePartFinding(Severity::Error, Code::DrawingPlacedOtherwise, m, tp, program,
                                      "the program cuts the drawing " + how + ": " + fit + ", and as placed " +
                                          std::to_string(m.out.outOfTolerance) + " of its " +
                                          std::to_string(drawing.size()) + " elements lie off",
                                      a.placement.mirror
                                          ? "a mirrored part is another part: mirror the program back"
                                          : "--drawing-origin places the drawing; --align takes the placement found"));
        return std::move(m.out);
      }
    }
  }
  reportAll(m, drawing, tp, options, program, drawingSource, diags);
  return std::move(m.out);
}

}  // namespace kerf::converter
