// The ruled surface the wire sweeps, one patch per move.
//
// A patch joins a lower segment L (on z = planes.lower) and an upper segment U (on z =
// planes.upper): the wire at parameter t in [0, 1] is the straight generator from L(t) to U(t),
// with t proportional to arc length on each side (docs/taper.md). A point of the patch is
//   P(t, s) = ((1 - s) L(t) + s U(t), lower + s H),   s in [0, 1], H = upper - lower.
// Every evaluation here is exact; the extremes over t are exact where a closed form exists
// (line paired with line) and sampled-and-refined otherwise (docs/geometry.md says which).
#pragma once

#include "kerf/geometry/segment.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace kerf::geometry {

struct Planes {
  double lower = 0.0;  ///< z of the lower contour, mm
  double upper = 1.0;  ///< z of the upper contour, mm (> lower)
  [[nodiscard]] double height() const { return upper - lower; }
};

Vec3 surfacePoint(const Segment& lower, const Segment& upper, const Planes& planes, double t, double s);

/// Unit normal dP/dt x dP/ds (zero where the patch degenerates, e.g. an upper side of length 0
/// at s = 1). For a counter-clockwise contour cut with a vertical wire it points outwards.
Vec3 surfaceNormal(const Segment& lower, const Segment& upper, const Planes& planes, double t, double s);

/// Slope of the wire at t: the angle between the generator and +z, radians.
double slopeAt(const Segment& lower, const Segment& upper, const Planes& planes, double t);

struct Extreme {
  double value = 0.0;
  double t = 0.0;
};

/// The measures of one patch that the checks and the report use.
struct PatchMeasures {
  Extreme minSlope, maxSlope;      ///< radians
  Extreme maxOffsetX, maxOffsetY;  ///< largest |U(t) - L(t)| per axis, mm
  bool exact = false;              ///< closed form (line with line); else sampled and refined
};

/// Line with line: closed form. Otherwise kExtremeSamples + 1 samples, each extreme refined by
/// safeguarded Newton steps (exact first and second derivatives) to 1e-12 in t around its best
/// sample.
inline constexpr int kExtremeSamples = 64;
PatchMeasures measurePatch(const Segment& lower, const Segment& upper, const Planes& planes);

/// Area of the patch, mm^2: Gauss-Legendre quadrature (5 x 5 points per piece, arcs split into
/// pieces of at most pi/8), exact for planar patches and within 1e-9 relative on the others.
double patchArea(const Segment& lower, const Segment& upper, const Planes& planes);

/// How far the upper direction of travel turns away from the lower one over the patch. The
/// tangent angles of lines and arcs are linear in t, so the largest angle is found exactly.
struct TwistMeasure {
  double maxAngle = 0.0;  ///< radians, in [0, pi]
  double t = 0.0;         ///< where it is largest
  bool defined = false;   ///< false when a side has length zero (a point: no direction)
};
TwistMeasure measureTwist(const Segment& lower, const Segment& upper);

/// Where two consecutive patches (a ends where b starts) fold onto each other: the height s in
/// (0, 1) at which the section turns back by exactly 180 degrees at their joint (the section
/// directions there, (1 - s) L' + s U', are linear in s, so this is the root of a quadratic:
/// exact). Nothing when they never do.
std::optional<double> foldAtJoint(const Segment& lowerA, const Segment& upperA, const Segment& lowerB,
                                  const Segment& upperB);

/// A polyline section has at most this many pieces (a patch with a huge arc would otherwise make
/// millions); beyond it the tolerance is not met.
inline constexpr std::size_t kMaxSectionPieces = 4096;

/// The horizontal section of the patch at s, appended to out: one segment when the section is a
/// line or an arc (line with line, exact; two arcs with the same sweep, exact — two vectors turning
/// at the same rate add up to one — or with sweeps that differ by d where d max(r) is within
/// half the tolerance), otherwise a polyline within tolerance of it. Returns true when exact.
/// maxPieces (at most kMaxSectionPieces) caps the polyline: a caller with a budget for a whole
/// section (sectionPieces counts first) gives each patch its share.
bool appendSection(const Segment& lower, const Segment& upper, double s, double tolerance, std::vector<Segment>& out,
                   std::size_t maxPieces = kMaxSectionPieces);

/// How many segments appendSection appends for the patch at s (without maxPieces), without making
/// them.
std::size_t sectionPieces(const Segment& lower, const Segment& upper, double s, double tolerance);

// ---- meshes ------------------------------------------------------------------------------------

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<float> vertexSlope;  ///< slope of the generator the vertex lies on, radians (as slopeAt)
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise about the normal
  std::vector<std::uint32_t> trianglePatch;             ///< patch index per triangle (caps: kCapPatch)
  std::size_t capsMade = 0;
  bool truncated = false;  ///< MeshOptions::maxTriangles was reached: the mesh is incomplete
};
inline constexpr std::uint32_t kCapPatch = 0xFFFFFFFFu;

/// Limits of one patch's mesh: pieces along t, and pieces along s of one generator. Beyond them
/// the tolerance is not met (a huge arc, a wildly twisted patch) rather than memory exhausted.
inline constexpr std::size_t kMaxMeshPieces = 4096;
inline constexpr std::uint32_t kMaxMeshCuts = 256;

struct MeshOptions {
  double tolerance = 0.01;  ///< mm: largest distance between the mesh and the exact surface
  bool lowerCap = false;    ///< close a closed lower contour with a flat cap (ear clipping)
  bool upperCap = false;
  std::size_t maxCapVertices = 20000;     ///< ear clipping is O(n^2): larger caps are left open
  std::size_t maxTriangles = 50'000'000;  ///< stop (Mesh::truncated) rather than exhaust memory
  /// At least this many pieces along t in a patch whose generators are not all vertical, so
  /// values that vary along it (the slope) are sampled inside the patch, not only at its ends.
  std::size_t minTaperPieces = 1;
  /// Those forced pieces (not the tolerance's) are no shorter than this, mm along the longer
  /// contour: a picture sets it to its pixel, as pieces narrower than a pixel show nothing.
  double minForcedPieceLength = 0.0;
};

/// Triangulates the patches (lower[i], upper[i]) into one mesh. Consecutive patches that share
/// their joining generator share its vertices, so a closed contour gives a closed tube and every
/// interior edge is used by exactly two triangles. Half the tolerance goes to the chords of arcs
/// (along t), half to the twist of each cell (the generators are split along s until the
/// triangles are within it of the bilinear cell).
Mesh meshRuledSurface(std::span<const Segment> lower, std::span<const Segment> upper, const Planes& planes,
                      const MeshOptions& options = {});

}  // namespace kerf::geometry
