// The scene drawn (scene.h): the toolpath's lines, surfaces and markers, in float vertices.
// Sections: 1. colours and vertices  2. planes and bounds  3. runs and the cut surface
//           4. what the scene holds  5. building the scene
#include "kerf/render/scene.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/contour.h"

#include "kerf/geometry/tessellation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kerf::render {

using converter::Severity;
using geometry::Segment;
using geometry::Vec2;
using geometry::Vec3;

namespace {

constexpr std::uint32_t kLowerColour = rgba(20, 70, 160);
constexpr std::uint32_t kUpperColour = rgba(200, 90, 20);
constexpr std::uint32_t kGeneratorColour = rgba(70, 75, 90, 70);
constexpr std::uint32_t kRapidColour = rgba(110, 110, 110, 200);
constexpr std::uint32_t kReferenceColour = rgba(200, 60, 150, 230);  // the drawing: magenta, dashed
constexpr std::uint32_t kGuideColour = rgba(20, 150, 160, 255);      // the guides' paths: teal
constexpr std::uint32_t kGuideWireColour = rgba(20, 150, 160, 110);  // the wire extended between them
constexpr std::uint32_t kVertexDone = 0x80000000u;                   // buildScene's mark while it finishes a patch

// ---- 1. colours and vertices --------------------------------------------------------------------

std::array<float, 3> toFloat(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

/// The segment as a polyline within `tolerance` of it, at height z.
void addSegment(LineSet& set, const Segment& seg, double z, const geometry::Sampling& sampling, std::uint32_t colour,
                std::vector<Vec2>& scratch) {
  scratch.assign(1, seg.start);
  geometry::sample(seg, sampling, &scratch);  // appends the points after the start
  for (std::size_t i = 0; i + 1 < scratch.size(); ++i)
    set.add({scratch[i].x(), scratch[i].y(), z}, {scratch[i + 1].x(), scratch[i + 1].y(), z}, colour);
}

std::uint32_t severityColour(Severity s) {
  switch (s) {
    case Severity::Error: return rgba(220, 30, 30);
    case Severity::Warning: return rgba(240, 160, 0);
    case Severity::Note: return rgba(40, 120, 230);
  }
  return rgba(220, 30, 30);
}

/// --color-by deviation: the part edge's pieces in their deviation's colour, each plane at its
/// height, and a marker at the worst point of both with its figure.
void addDeviationEdge(Scene& scene, const SceneOptions& options, const geometry::Planes& planes,
                      const geometry::Sampling& sampling, std::vector<Vec2>& scratch) {
  scene.deviation.moveFirst.push_back(0);
  const SceneOptions::DeviationEdge* worstPlane = nullptr;
  std::size_t worst = 0;
  double worstZ = 0.0;
  for (const auto& [edge, z] :
       {std::pair{&options.deviationLower, planes.lower}, std::pair{&options.deviationUpper, planes.upper}})
    for (std::size_t k = 0; k < edge->pieces.size() && k < edge->deviations.size(); ++k) {
      const double d = edge->deviations[k];
      const double x = options.deviationScale > 0 ? d / options.deviationScale : 0.0;
      addSegment(scene.deviation, edge->pieces[k], z, sampling, rampColour(x), scratch);
      if (!worstPlane || d > worstPlane->deviations[worst]) {
        worstPlane = edge;
        worst = k;
        worstZ = z;
      }
    }
  scene.deviation.moveFirst.push_back(static_cast<std::uint32_t>(scene.deviation.vertices.size()));
  if (!worstPlane) return;
  // The worst point: where along the worst piece is the caller's to say; its middle marks it.
  Marker m;
  const Vec2 at = worstPlane->pieces[worst].pointAt(0.5);
  m.position = {at.x(), at.y(), worstZ};
  m.colour = rgba(200, 60, 150);
  m.sizePixels = 12.0f;
  m.label = "worst " + converter::formatFixed(worstPlane->deviations[worst] * 1000.0, 1) + " um";
  scene.findings.push_back(std::move(m));
}

}  // namespace

std::uint32_t rampColour(double x) {
  constexpr double stops[5][3] = {
      {0.19, 0.30, 0.80}, {0.10, 0.70, 0.85}, {0.25, 0.75, 0.30}, {0.95, 0.80, 0.15}, {0.85, 0.20, 0.15}};
  x = std::clamp(x, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(x));
  const double f = x - i;
  auto channel = [&](int k) {
    return static_cast<std::uint8_t>(std::lround(255.0 * (stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f)));
  };
  return rgba(channel(0), channel(1), channel(2));
}

// ---- 2. planes and bounds -----------------------------------------------------------------------

void LineSet::add(const Vec3& a, const Vec3& b, std::uint32_t colour) {
  vertices.push_back({toFloat(a), colour});
  vertices.push_back({toFloat(b), colour});
}

SceneOptions coarseSceneOptions(SceneOptions exact, double mmPerPixel) {
  exact.tolerance = std::max(exact.tolerance, 0.5 * mmPerPixel);
  exact.mergeTolerance = 0.5 * mmPerPixel;
  exact.minTaperPieces = 1;
  return exact;
}

geometry::Planes displayPlanes(const converter::Toolpath& toolpath, double displayHeight) {
  if (toolpath.isTaper() && toolpath.heights.known) return toolpath.heights.planes;
  geometry::Box box;
  for (const auto& m : toolpath.moves) {
    box.add(m.lower.start);
    box.add(m.lower.end);
  }
  double h = displayHeight;
  if (h <= 0.0) {
    const double size = toolpath.moves.empty() ? 1.0 : std::max((box.max - box.min).norm(), 1e-3);
    h = 0.08 * size;
  }
  const double lower = toolpath.heights.known ? toolpath.heights.planes.lower : 0.0;
  return {lower, lower + h};
}

void toolpathBounds(const converter::Toolpath& toolpath, double displayHeight, Vec3& lo, Vec3& hi) {
  const geometry::Planes planes = displayPlanes(toolpath, displayHeight);
  geometry::Box box;
  box.add(toolpath.start);
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const geometry::Box b = toolpath.moves[i].lower.bounds();
    box.add(b.min);
    box.add(b.max);
    if (toolpath.isTaper()) {
      const geometry::Box u = toolpath.upperOf(i).bounds();
      box.add(u.min);
      box.add(u.max);
    }
  }
  lo = {box.min.x(), box.min.y(), planes.lower};
  hi = {box.max.x(), box.max.y(), planes.upper};
}

namespace {

// ---- 3. runs and the cut surface ----------------------------------------------------------------

/// How far the segment strays from the chord p..q, at most (its ends' distances, plus its own
/// bulge for an arc: the distance to a segment is convex along the arc's chord).
double strayFrom(const Segment& s, const Vec2& p, const Vec2& q) {
  auto distance = [&](const Vec2& x) {
    const Vec2 d = q - p;
    const double dd = d.squaredNorm();
    const double t = dd > 0 ? std::clamp((x - p).dot(d) / dd, 0.0, 1.0) : 0.0;
    return (x - (p + t * d)).norm();
  };
  double bulge = 0.0;
  if (s.isArc()) bulge = std::abs(s.sweep) >= geometry::kPi ? 2 * s.radius() : s.radius() * (1 - std::cos(s.sweep / 2));
  return std::max(distance(s.start), distance(s.end)) + bulge;
}

}  // namespace

std::vector<std::size_t> displayRuns(const converter::Toolpath& toolpath, double tolerance) {
  constexpr std::size_t kMaxRun = 64;  // the merge re-tests its run at each step: O(n kMaxRun)
  constexpr double kJoin = 1e-9;
  const std::size_t n = toolpath.moves.size();
  std::vector<std::size_t> end(n);
  for (std::size_t i = 0; i < n; ++i) end[i] = i + 1;
  if (tolerance <= 0.0) return end;
  std::size_t i = 0;
  while (i < n) {
    std::size_t j = i + 1;  // [i, j) merged so far
    if (toolpath.moves[i].isCut()) {
      while (j < n && j - i < kMaxRun && toolpath.moves[j].isCut() &&
             (toolpath.moves[j].lower.start - toolpath.moves[j - 1].lower.end).norm() <= kJoin &&
             (toolpath.upperOf(j).start - toolpath.upperOf(j - 1).end).norm() <= kJoin) {
        const Vec2 lp = toolpath.moves[i].lower.start, lq = toolpath.moves[j].lower.end;
        const Vec2 up = toolpath.upperOf(i).start, uq = toolpath.upperOf(j).end;
        bool fits = true;
        for (std::size_t k = i; k <= j && fits; ++k)
          fits = strayFrom(toolpath.moves[k].lower, lp, lq) <= tolerance &&
                 strayFrom(toolpath.upperOf(k), up, uq) <= tolerance;
        if (!fits) break;
        ++j;
      }
    }
    end[i] = j;
    i = j;
  }
  return end;
}

CutSurface meshCutSurface(const converter::Toolpath& toolpath, const SceneOptions& options, bool caps) {
  CutSurface out;
  out.planes = displayPlanes(toolpath, options.displayHeight);
  std::vector<Segment> lowerCut, upperCut;
  const std::vector<std::size_t> runEnd = displayRuns(toolpath, options.mergeTolerance);
  for (std::size_t i = 0; i < toolpath.moves.size(); i = runEnd[i]) {
    if (!toolpath.moves[i].isCut()) continue;
    const std::size_t last = runEnd[i] - 1;
    if (last == i) {
      lowerCut.push_back(toolpath.moves[i].lower);
      upperCut.push_back(toolpath.upperOf(i));
    } else {
      lowerCut.push_back(Segment::line(toolpath.moves[i].lower.start, toolpath.moves[last].lower.end));
      upperCut.push_back(Segment::line(toolpath.upperOf(i).start, toolpath.upperOf(last).end));
    }
    out.patchMove.push_back(i);
    out.patchEnd.push_back(runEnd[i]);
  }
  if (caps) {
    // The solid is the closed contour: a loop on both planes. The patches before and after it
    // (the lead paths) are left out.
    constexpr double kClose = 1e-6;
    const geometry::ClosureReport closure = geometry::analyseClosure(lowerCut, kClose);
    if (closure.loopFrom && closure.loopTo &&
        (upperCut[*closure.loopTo].end - upperCut[*closure.loopFrom].start).norm() <= kClose) {
      const std::size_t from = *closure.loopFrom, to = *closure.loopTo + 1;
      out.leadPatchesLeftOut = lowerCut.size() - (to - from);
      auto keep = [&](auto& v) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(to), v.end());
        v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(from));
      };
      keep(lowerCut);
      keep(upperCut);
      keep(out.patchMove);
      keep(out.patchEnd);
    }
  }
  geometry::MeshOptions meshOptions;
  meshOptions.tolerance = options.tolerance;
  meshOptions.maxTriangles = options.maxTriangles;
  meshOptions.lowerCap = meshOptions.upperCap = caps;
  meshOptions.minTaperPieces = options.minTaperPieces;
  meshOptions.minForcedPieceLength = options.minForcedPieceLength;
  out.mesh = geometry::meshRuledSurface(lowerCut, upperCut, out.planes, meshOptions);
  return out;
}

namespace {

// ---- 4. what the scene holds --------------------------------------------------------------------

/// The findings' markers (errors and warnings, notes when asked) with their labels; which moves
/// have an error or a warning (their surface is tinted).
std::vector<bool> addFindingMarkers(Scene& scene, const converter::Toolpath& toolpath,
                                    std::span<const converter::Diagnostic> findings, const SceneOptions& options) {
  const std::size_t n = toolpath.moves.size();
  std::vector<bool> flagged(n, false);
  for (const auto& d : findings) {
    if (d.move && *d.move < n && d.severity != Severity::Note) flagged[*d.move] = true;
    if (!d.point || (d.severity == Severity::Note && !options.noteMarkers)) continue;
    Marker m;
    m.position = *d.point;
    m.severity = d.severity;
    m.colour = severityColour(d.severity);
    m.sizePixels = d.severity == Severity::Error ? 12.0f : 10.0f;
    std::uint32_t line = 0;
    if (d.move && *d.move < n) {
      m.move = *d.move;
      line = toolpath.moves[*d.move].line;
    } else if (d.source != nullptr && !d.span.isWholeFile()) {
      line = d.source->locate(d.span.offset).line;
    }
    m.label = converter::codeName(d.code) + (line ? " line " + std::to_string(line) : std::string());
    scene.findings.push_back(std::move(m));
  }

  return flagged;
}

/// The cut surface's triangles, each patch with its own vertices, normals and slopes.
void addSurface(Scene& scene, const CutSurface& cut, const std::vector<bool>& flagged, const SceneOptions& options) {
  const geometry::Mesh& mesh = cut.mesh;
  const std::vector<std::size_t>& cutMove = cut.patchMove;
  scene.truncated = mesh.truncated;

  // Normals are averaged over the triangles of one patch only, so the corners between patches
  // stay sharp: each patch gets its own copy of the vertices it uses, shared by its triangles
  // (about one vertex a triangle along a strip, not three: the indexed mesh is what the GPU and
  // llvmpipe's vertex stage see).
  scene.surface.reserve(mesh.vertices.size() + 4 * cutMove.size());
  scene.surfaceIndices.reserve(mesh.triangles.size() * 3);
  scene.triangleMove.reserve(mesh.triangles.size());
  std::vector<Vec3> normalSum(mesh.vertices.size(), Vec3::Zero());
  std::vector<std::uint32_t> stamp(mesh.vertices.size(), 0);
  std::vector<std::uint32_t> slot(mesh.vertices.size(), 0);  // the vertex's index in this patch's copy
  std::uint32_t run = 0;
  std::size_t t0 = 0;
  bool anySlope = false;
  while (t0 < mesh.triangles.size()) {
    std::size_t t1 = t0;
    const std::uint32_t patch = mesh.trianglePatch[t0];
    while (t1 < mesh.triangles.size() && mesh.trianglePatch[t1] == patch) ++t1;
    if (patch < cutMove.size() && cutMove[patch] < options.hiddenMoves.size() && options.hiddenMoves[cutMove[patch]]) {
      t0 = t1;  // a hidden move draws no surface
      continue;
    }
    ++run;
    const std::size_t patchFirst = scene.surface.size();
    for (std::size_t t = t0; t < t1; ++t) {
      const auto& tri = mesh.triangles[t];
      const Vec3 fn =
          (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
      scene.surfaceArea += 0.5 * fn.norm();
      for (const std::uint32_t v : tri) {
        if (stamp[v] != run) {
          normalSum[v] = Vec3::Zero();
          stamp[v] = run;
          slot[v] = static_cast<std::uint32_t>(scene.surface.size());
          scene.surface.push_back({toFloat(mesh.vertices[v]), {0, 0, 0}, 0.0f, 0u});
        }
        normalSum[v] += fn;
        scene.surfaceIndices.push_back(slot[v]);
      }
    }
    const std::size_t move = patch < cutMove.size() ? cutMove[patch] : SIZE_MAX;
    bool onFinding = false;
    if (move != SIZE_MAX)
      for (std::size_t k = move; k < cut.patchEnd[patch] && !onFinding; ++k) onFinding = flagged[k];
    std::uint32_t flags = onFinding ? kOnFinding : 0u;
    if (move < options.movePass.size()) flags |= std::uint32_t{options.movePass[move]} << kPassShift;
    // The patch's vertices, in the order they were met: finish each once.
    for (std::size_t t = t0; t < t1; ++t) {
      for (const std::uint32_t v : mesh.triangles[t]) {
        SurfaceVertex& out = scene.surface[slot[v]];
        if (out.flags & kVertexDone) continue;
        const double len = normalSum[v].norm();
        const Vec3 nrm = len > 0 ? Vec3(normalSum[v] / len) : Vec3(0, 0, 1);
        const double slope = static_cast<double>(mesh.vertexSlope[v]) * 180.0 / geometry::kPi;
        if (!anySlope || slope < scene.minSlopeDegrees) scene.minSlopeDegrees = slope;
        if (!anySlope || slope > scene.maxSlopeDegrees) scene.maxSlopeDegrees = slope;
        anySlope = true;
        out.normal = toFloat(nrm);
        out.slopeDegrees = static_cast<float>(slope);
        out.flags = kVertexDone;
      }
      scene.triangleMove.push_back(static_cast<std::uint32_t>(std::min<std::size_t>(move, 0xFFFFFFFFu)));
    }
    for (std::size_t i = patchFirst; i < scene.surface.size(); ++i) scene.surface[i].flags = flags;
    t0 = t1;
  }
}

/// The contours, rapids and generator lines, per move, so a move can be drawn again selected.
void addMoveLines(Scene& scene, const converter::Toolpath& toolpath, const CutSurface& cut, const SceneOptions& options,
                  const geometry::Sampling& sampling, std::vector<Vec2>& scratch) {
  const geometry::Planes& planes = scene.planes;
  const std::size_t n = toolpath.moves.size();
  const std::vector<std::size_t>& cutMove = cut.patchMove;
  double cutLength = 0.0;
  for (std::size_t i : cutMove) cutLength += toolpath.moves[i].lower.length();
  const double spacing = cutLength / static_cast<double>(std::max<std::size_t>(options.generators, 1));
  double untilNext = 0.0;
  for (LineSet* set : {&scene.lower, &scene.upper, &scene.generators, &scene.rapids}) set->moveFirst.reserve(n + 1);
  // A merged run (SceneOptions::mergeTolerance) is drawn as its chords at its first move; the
  // moves inside it draw nothing of their own.
  std::vector<std::size_t> runEnd(n);
  for (std::size_t k = 0; k < n; ++k) runEnd[k] = k + 1;
  for (std::size_t p = 0; p < cutMove.size(); ++p) runEnd[cutMove[p]] = cut.patchEnd[p];
  std::size_t insideUntil = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (LineSet* set : {&scene.lower, &scene.upper, &scene.generators, &scene.rapids})
      set->moveFirst.push_back(static_cast<std::uint32_t>(set->vertices.size()));
    if (i < insideUntil || (i < options.hiddenMoves.size() && options.hiddenMoves[i])) continue;
    const std::size_t last = runEnd[i] - 1;
    insideUntil = runEnd[i];
    // A merged run's chords (made only for a run: a plain move draws its own segments).
    Segment chordLower, chordUpper;
    if (last != i) {
      chordLower = Segment::line(toolpath.moves[i].lower.start, toolpath.moves[last].lower.end);
      chordUpper = Segment::line(toolpath.upperOf(i).start, toolpath.upperOf(last).end);
    }
    const Segment& lower = last == i ? toolpath.moves[i].lower : chordLower;
    const Segment& up = last == i ? toolpath.upperOf(i) : chordUpper;
    if (!toolpath.moves[i].isCut()) {
      addSegment(scene.rapids, lower, planes.lower, sampling, kRapidColour, scratch);
      if (scene.taper) addSegment(scene.rapids, up, planes.upper, sampling, kRapidColour, scratch);
      continue;
    }
    const std::uint8_t pass = i < options.movePass.size() ? options.movePass[i] : 0;
    scene.passes = std::max<std::size_t>(scene.passes, pass);
    const bool passColoured = options.passLines && pass > 0;
    addSegment(scene.lower, lower, planes.lower, sampling, passColoured ? passColour(pass) : kLowerColour, scratch);
    addSegment(scene.upper, up, planes.upper, sampling, passColoured ? passColour(pass) : kUpperColour, scratch);
    // Generators every `spacing` mm of the lower contour, and at every move's start (corners).
    if (options.generators == 0) continue;
    const double len = lower.length();
    auto generatorAt = [&](double t) {
      const Vec2 a = lower.pointAt(t), b = up.pointAt(t);
      scene.generators.add({a.x(), a.y(), planes.lower}, {b.x(), b.y(), planes.upper}, kGeneratorColour);
    };
    generatorAt(0.0);
    double at = untilNext;
    while (spacing > 0 && at < len) {
      if (at > 1e-9 * (len + 1)) generatorAt(at / len);
      at += spacing;
    }
    untilNext = at - len;
  }
  for (LineSet* set : {&scene.lower, &scene.upper, &scene.generators, &scene.rapids})
    set->moveFirst.push_back(static_cast<std::uint32_t>(set->vertices.size()));
}

/// The wire at its guides: each cut move's positions at the guides (its lower and upper segments at
/// the same t, extended: lower + (upper - lower)(z - z_lower)/H) drawn at the guides' heights, and
/// the whole wire from guide to guide at each move's start.
void addGuides(Scene& scene, const converter::Toolpath& toolpath, const geometry::Sampling& sampling) {
  scene.guides.moveFirst.push_back(0);
  const geometry::Planes& faces = toolpath.heights.planes;
  const geometry::Planes& guides = *toolpath.heights.guides;
  const double a = (guides.lower - faces.lower) / faces.height(), b = (guides.upper - faces.lower) / faces.height();
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    if (!toolpath.moves[i].isCut()) continue;
    const Segment& lo = toolpath.moves[i].lower;
    const Segment& up = toolpath.upper[i];
    const std::size_t n = std::max<std::size_t>(
        1, std::min<std::size_t>(4096,
                                 std::max(geometry::sampleCount(lo, sampling), geometry::sampleCount(up, sampling))));
    auto at = [&](double t, double s, double z) {
      const Vec2 l = lo.pointAt(t), u = up.pointAt(t);
      const Vec2 p = l + s * (u - l);
      return Vec3{p.x(), p.y(), z};
    };
    scene.guides.add(at(0.0, a, guides.lower), at(0.0, b, guides.upper), kGuideWireColour);
    for (std::size_t k = 0; k < n; ++k) {
      const double t0 = static_cast<double>(k) / static_cast<double>(n),
                   t1 = static_cast<double>(k + 1) / static_cast<double>(n);
      scene.guides.add(at(t0, a, guides.lower), at(t1, a, guides.lower), kGuideColour);
      scene.guides.add(at(t0, b, guides.upper), at(t1, b, guides.upper), kGuideColour);
    }
  }
  scene.guides.moveFirst.push_back(static_cast<std::uint32_t>(scene.guides.vertices.size()));
}

/// The box of everything drawn (the start, the surface, the lines), between the planes at least.
void setBounds(Scene& scene) {
  const geometry::Planes& planes = scene.planes;
  // Bounds of everything drawn.
  Vec3 lo = scene.start, hi = scene.start;
  auto grow = [&](const std::array<float, 3>& p) {
    const Vec3 v{p[0], p[1], p[2]};
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  };
  for (const auto& v : scene.surface) grow(v.position);
  for (const LineSet* set :
       {&scene.lower, &scene.upper, &scene.rapids, &scene.reference, &scene.deviation, &scene.guides})
    for (const auto& v : set->vertices) grow(v.position);
  lo.z() = std::min(lo.z(), planes.lower);
  hi.z() = std::max(hi.z(), planes.upper);
  scene.boundsMin = lo;
  scene.boundsMax = hi;
}

}  // namespace

// ---- 5. building the scene ----------------------------------------------------------------------

Scene buildScene(const converter::Toolpath& toolpath, std::span<const converter::Diagnostic> findings,
                 const SceneOptions& options, std::span<const geometry::Segment> reference) {
  Scene scene;
  scene.taper = toolpath.isTaper();
  scene.moves = toolpath.moves.size();
  const CutSurface cut = meshCutSurface(toolpath, options);
  scene.planes = cut.planes;
  const geometry::Planes& planes = scene.planes;
  const std::vector<bool> flagged = addFindingMarkers(scene, toolpath, findings, options);
  addSurface(scene, cut, flagged, options);
  // Lines within the tolerance (or the picture's finer line tolerance).
  const geometry::Sampling sampling = geometry::Sampling::tolerance(std::max(options.tolerance, options.lineTolerance));
  std::vector<Vec2> scratch;
  addMoveLines(scene, toolpath, cut, options, sampling, scratch);
  scene.reference.moveFirst.push_back(0);
  for (const Segment& s : reference) addSegment(scene.reference, s, planes.lower, sampling, kReferenceColour, scratch);
  for (const Segment& s : options.referenceUpper)
    addSegment(scene.reference, s, planes.upper, sampling, kReferenceColour, scratch);
  scene.reference.moveFirst.push_back(static_cast<std::uint32_t>(scene.reference.vertices.size()));
  addDeviationEdge(scene, options, planes, sampling, scratch);
  if (options.showGuides && scene.taper && toolpath.heights.guides && toolpath.heights.known)
    addGuides(scene, toolpath, sampling);
  scene.start = {toolpath.start.x(), toolpath.start.y(), planes.lower};
  setBounds(scene);
  return scene;
}

}  // namespace kerf::render
