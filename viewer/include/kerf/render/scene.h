// What the renderer draws, built from a Toolpath and its findings. Plain data: no GL here, so the
// window, the headless renderer, the exporter and the tests share one description of the part.
//
// Coordinates are the program's, in mm, z up: the lower contour lies on Planes::lower and the
// upper one on Planes::upper. A 2-axis program's wire is vertical, so its surface is the lower
// contour swept up to a display height (SceneOptions::displayHeight).
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/ruled_surface.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace kerf::render {

/// Colours are 0xAABBGGRR (byte order R, G, B, A in memory, as GL reads GL_UNSIGNED_BYTE x4).
constexpr std::uint32_t rgba(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
  return std::uint32_t{r} | (std::uint32_t{g} << 8) | (std::uint32_t{b} << 16) | (std::uint32_t{a} << 24);
}

struct SurfaceVertex {
  std::array<float, 3> position;
  std::array<float, 3> normal;  ///< unit, outward for a counter-clockwise contour
  float slopeDegrees;           ///< slope of the wire through this point
  std::uint32_t flags;          ///< kOnFinding: the move has an error or warning finding
};
inline constexpr std::uint32_t kOnFinding = 1u;
/// SurfaceVertex::flags bits 8-15: the pass the vertex's move belongs to (SceneOptions::movePass).
inline constexpr std::uint32_t kPassShift = 8u;

/// Colours of passes 1, 2, ... (the rough cut first), repeating after kPassColours: the surface
/// shader, the contour lines and the legend take them from here.
inline constexpr std::size_t kPassColours = 6;
constexpr std::uint32_t passColour(std::size_t pass) {
  constexpr std::uint32_t colours[kPassColours] = {rgba(205, 60, 45),  rgba(40, 110, 200), rgba(50, 160, 80),
                                                   rgba(225, 150, 20), rgba(140, 70, 170), rgba(30, 160, 170)};
  return colours[(pass == 0 ? 0 : pass - 1) % kPassColours];
}

/// The ramp the slope and deviation colours run along, from 0 (blue) through cyan, green and
/// yellow to 1 (red); outside [0, 1] clamped. The surface shader's slope ramp has the same stops.
std::uint32_t rampColour(double x);

struct LineVertex {
  std::array<float, 3> position;
  std::uint32_t colour;
};

/// Line segments (pairs of vertices). moveFirst[m]..moveFirst[m+1] are the vertices of move m,
/// so one move can be drawn again highlighted; segmentMove gives the move of each segment.
struct LineSet {
  std::vector<LineVertex> vertices;
  std::vector<std::uint32_t> moveFirst;
  void add(const geometry::Vec3& a, const geometry::Vec3& b, std::uint32_t colour);
};

struct Marker {
  geometry::Vec3 position;
  std::uint32_t colour = 0;
  float sizePixels = 10.0f;
  std::string label;            ///< "K0651 line 12"
  std::size_t move = SIZE_MAX;  ///< SIZE_MAX: not tied to a move
  converter::Severity severity = converter::Severity::Note;
};

struct SceneOptions {
  double tolerance = 0.01;      ///< mm: largest distance of the drawn surface and contours from the exact ones
  double displayHeight = 0.0;   ///< 2-axis parts: height of the wall drawn, mm (0: 8 % of the part's size)
  std::size_t generators = 72;  ///< about this many generator lines along the whole cut (0: none)
  std::size_t maxTriangles = 20'000'000;
  std::size_t minTaperPieces = 16;  ///< pieces along a leaning patch at least, so the slope colours vary inside it
  /// mm: those forced pieces are no shorter than this (a picture's pixel: finer shows nothing).
  double minForcedPieceLength = 0.0;
  /// mm: the lines' chord tolerance when coarser than `tolerance` (a picture: a quarter pixel).
  double lineTolerance = 0.0;
  /// mm: runs of joined cuts whose contours stay this close to the chords from the run's start to
  /// its end are drawn as one patch of those chords (0: never). The window's moving frames: the
  /// detail under half a pixel, lines and surface alike, left out (displayRuns).
  double mergeTolerance = 0.0;
  bool noteMarkers = false;  ///< notes get markers too (errors and warnings always do)
  /// --show guides: a taper program's guide paths (PlaneHeights::guides) and the wire extended to
  /// them at every move's start, in Scene::guides. Nothing where the heights are unknown.
  bool showGuides = false;
  /// Each move's pass in its contour (1 = the first, the rough cut; 0 = in none), one entry a move
  /// (converter::movePasses): the surface carries it for RenderOptions::colourByPass. Empty: none.
  std::vector<std::uint8_t> movePass;
  bool passLines = false;  ///< the contour lines in their pass's colour too (kerf render --color-by pass)
  /// --color-by deviation: the part edge held against --drawing (converter::DrawingComparison::
  /// edge), each piece coloured by its deviation along rampColour over [0, deviationScale] mm,
  /// with a marker at the worst; the lower plane, and a taper's upper plane against its own
  /// drawing (--drawing-upper). Empty: none.
  struct DeviationEdge {
    std::vector<geometry::Segment> pieces;
    std::vector<double> deviations;  ///< mm, one a piece
  };
  DeviationEdge deviationLower, deviationUpper;
  double deviationScale = 0.0;  ///< mm at the ramp's red end
  /// A taper's upper plane as drawn (--drawing-upper), dashed at the upper plane beside the
  /// program's, as buildScene's reference is at the lower. Empty: none.
  std::vector<geometry::Segment> referenceUpper;
  /// Moves left out of the picture (the window's hidden passes), one entry a move; empty: none.
  /// They keep their index: picking and the text panel still name moves as the toolpath does.
  std::vector<bool> hiddenMoves;
};

struct Scene {
  /// The surface's vertices: each patch has its own copy of every vertex it uses, so normals are
  /// smooth inside a patch and the corners between patches stay sharp.
  std::vector<SurfaceVertex> surface;
  std::vector<std::uint32_t> surfaceIndices;  ///< triangles, three indices into surface each
  std::vector<std::uint32_t> triangleMove;
  LineSet lower, upper, generators, rapids;
  /// What the wire path was made from (converter::referenceGeometry): a drawing's contours, a
  /// program's contour under G41/G42, on the lower plane. One "move" (moveFirst {0, size}).
  LineSet reference;
  /// The part edge coloured by its deviation from the drawing (SceneOptions::deviationLower, deviationUpper), on
  /// the lower plane; one "move".
  LineSet deviation;
  /// The wire at its guides (SceneOptions::showGuides): both guides' paths and the wire extended
  /// between them at each cut move's start; one "move".
  LineSet guides;
  std::vector<Marker> findings;
  geometry::Vec3 start{0, 0, 0};
  geometry::Vec3 boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
  geometry::Planes planes;
  bool taper = false;
  bool truncated = false;  ///< the surface hit maxTriangles: drawn incomplete, said in the picture
  double minSlopeDegrees = 0.0, maxSlopeDegrees = 0.0;
  double surfaceArea = 0.0;  ///< mm^2, of the triangles drawn
  std::size_t moves = 0;
  std::size_t passes = 0;  ///< the largest pass number drawn (SceneOptions::movePass), 0 without
  [[nodiscard]] std::size_t triangles() const { return surfaceIndices.size() / 3; }
};

/// The ruled surface of the cut moves (rapids are not cut), meshed within `tolerance`, with the
/// move each patch of the mesh belongs to: mesh.trianglePatch[t] indexes patchMove.
struct CutSurface {
  geometry::Mesh mesh;
  std::vector<std::size_t> patchMove;
  std::vector<std::size_t> patchEnd;  ///< one past the last move of the patch (patchMove + 1 unless merged)
  geometry::Planes planes;
  /// With caps: cut patches outside the closed contour (lead-in, lead-out) left out of the solid.
  std::size_t leadPatchesLeftOut = 0;
};
/// For each move i, one past the last move of the run that starts at i: i + 1, or, with a
/// tolerance, further over joined cut moves whose lower and upper contours stay within it of the
/// chords from the run's start to its end (at most 64 moves a run). Entries inside a run are not
/// used.
std::vector<std::size_t> displayRuns(const converter::Toolpath& toolpath, double tolerance);

/// The cut surface as triangles. caps: a solid for CAD: the closed contour capped on both planes,
/// and a lead-in or lead-out, which would stand on it as a fin of no thickness (edges of three
/// faces), left out (leadPatchesLeftOut).
CutSurface meshCutSurface(const converter::Toolpath& toolpath, const SceneOptions& options, bool caps = false);

/// Builds the scene. findings are the check's diagnostics; those with a point become markers
/// (errors red, warnings amber, notes blue if noteMarkers) and those with a move flag that move's surface.
/// reference (may be empty) is drawn beside the path: the geometry it was made from.
Scene buildScene(const converter::Toolpath& toolpath, std::span<const converter::Diagnostic> findings,
                 const SceneOptions& options = {}, std::span<const geometry::Segment> reference = {});

/// The box a toolpath is drawn in (both contours between displayPlanes), before any scene is
/// built: what a picture needs to know its scale.
void toolpathBounds(const converter::Toolpath& toolpath, double displayHeight, geometry::Vec3& lo, geometry::Vec3& hi);

/// Above this many triangles a view shows a coarse scene where it must stay responsive: the window
/// while the view moves, the 3D page (export/part_page.h) always.
inline constexpr std::size_t kCoarseAboveTriangles = 250'000;

/// The coarse level of `exact` for a view at `mmPerPixel`: a surface within half a pixel of the
/// exact one, no forced pieces, and runs of moves within half a pixel of their chord drawn as one
/// patch (displayRuns).
SceneOptions coarseSceneOptions(SceneOptions exact, double mmPerPixel);

/// The planes a toolpath is drawn between (taper: its own; 2-axis: lower .. lower + display height).
geometry::Planes displayPlanes(const converter::Toolpath& toolpath, double displayHeight);

}  // namespace kerf::render
