// From a drawing to a program (`kerf cam`; seed 003, CAWEP; docs/cam.md).
//
// The drawing's closed contours (read_dxf.h, chained by geometry/chain.h) become one toolpath: each
// contour oriented (the wire on the right of travel unless asked otherwise), started at the vertex
// nearest the point asked for, entered by a lead-in line from its start hole, and either offset by
// the wire radius here (geometry/offset.h wireOffset: arc corners, interference removed) or left
// for the controller to offset (G41/G42 with D0, the way a Robofil post writes it). Contours inside
// others (holes) are cut first and are offset to the other side. The toolpath then goes through
// the emitter table and is read back and checked before anything is written.
#pragma once

#include "kerf/converter/formats/dxf/read_dxf.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/offset.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace kerf::converter {

/// Which side of a contour the wire runs on: outside (a punch: the part is inside the contour) or
/// inside (a die: the part is the material around the hole).
enum class WireSide : std::uint8_t { Outside, Inside };

/// The wire path of one closed contour.
struct ContourWire {
  double distance = 0.0;  ///< the signed offset along the contour's direction (> 0: left of travel)
  std::vector<std::vector<geometry::WirePiece>> loops;
  std::vector<geometry::LostRun> lost;
  bool refused = false;         ///< over the piece budget: nothing computed
  std::size_t tooMuchWork = 0;  ///< refused over the budget of exact tests: the budget (else 0)
  bool degenerate = false;      ///< the contour encloses no area (it runs back over itself): no wire path
};

/// The side at a nesting depth, when the outermost contours are on `outermost`: a hole in a part
/// is cut from inside, an island in a hole from outside.
inline WireSide sideAtDepth(WireSide outermost, int depth) {
  return (depth % 2 == 0) == (outermost == WireSide::Outside) ? WireSide::Outside : WireSide::Inside;
}

/// The wire path at `radius` on `side` of a closed contour (either direction of travel).
ContourWire offsetContour(std::span<const geometry::Segment> contour, double radius, WireSide side);

/// Diagnostics for a contour's wire path: elements the wire cannot reach (K0902), inside corners
/// smaller than the wire (K0903), a path that splits or vanishes (K0904), a refusal (K0905).
/// `number` is the contour's 1-based number in the drawing.
void reportContourWire(const ContourWire& wire, std::size_t number, const DrawingResult& drawing,
                       const geometry::Chain& chain, double radius, const SourceFile* source, Diagnostics& diags);

/// The wire path at `radius` of every closed contour of the drawing, each on the side its nesting
/// gives (the outermost on `side`, sideAtDepth), reported through reportContourWire; an empty
/// ContourWire for an open contour. One entry per drawing.contours.
std::vector<ContourWire> drawingWires(const DrawingResult& drawing, double radius, WireSide side,
                                      const SourceFile* source, Diagnostics& diags);

/// The order contours are cut in: holes before the contours that hold them (deepest first, by
/// drawing.depth), then the drawing's order. `chosen` are indices into drawing.contours.
std::vector<std::size_t> cuttingOrder(const DrawingResult& drawing, std::vector<std::size_t> chosen);

/// The drawing as a toolpath (what `kerf check` and `kerf render` show of a drawing): every contour
/// in cutting order, as its wire path where `wires` (drawingWires) has one, else as drawn, with a
/// rapid to each new start; each move names the drawing entity it comes from.
Toolpath drawingToolpath(const DrawingResult& drawing, const std::vector<ContourWire>* wires);

struct CamOptions {
  double offset = 0.0;                            ///< wire radius plus spark gap, mm
  WireSide side = WireSide::Outside;              ///< for the outermost contours; holes in them get the other side
  bool controllerOffset = false;                  ///< G41/G42 D0: the program carries the contour, the machine offsets
  std::optional<std::size_t> contour;             ///< 1-based: cut only this contour
  std::optional<geometry::Vec2> start;            ///< each contour starts at its vertex nearest this point
  std::optional<geometry::Vec2> entry;            ///< the start hole (one contour only): the lead-in comes from here
  double leadIn = 2.0;                            ///< mm: from the start hole to the contour when no --entry
  std::optional<bool> wireOnLeft;                 ///< nothing: the wire right of travel (G42)
  geometry::Vec2 shift = geometry::Vec2::Zero();  ///< added to every point of the drawing
  double tolerance = 1e-6;                        ///< mm
  /// Open contours too (a curve, a profile cut from the stock's edge): cut along them as drawn,
  /// from their first end, the wire centre on the line (an open contour has no inside or outside).
  bool openPaths = false;
};

struct CamContour {
  std::size_t number = 0;  ///< 1-based contour number in the drawing
  int depth = 0;           ///< how many other contours enclose it
  WireSide side = WireSide::Outside;
  bool open = false;         ///< cut along as drawn (CamOptions::openPaths)
  std::size_t elements = 0;  ///< contour elements cut
  double contourLength = 0.0, area = 0.0;
  double wireLength = 0.0;  ///< length of the wire path (the contour itself with controllerOffset)
};

struct CamResult {
  Toolpath toolpath;
  std::vector<CamContour> contours;
  double cutLength = 0.0;  ///< every cutting move, lead-ins included
};

/// The toolpath of a program for the drawing's closed contours; nothing, with errors, when no
/// contour can be cut.
std::optional<CamResult> makeProgram(const DrawingResult& drawing, const SourceFile* source, const CamOptions& options,
                                     Diagnostics& diags);

}  // namespace kerf::converter
