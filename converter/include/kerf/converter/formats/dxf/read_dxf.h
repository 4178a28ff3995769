// DXF drawings (FORMATS §8, docs/dxf.md): the entities that carry a wire contour, read into lines
// and arcs in mm, for `kerf cam` and for `kerf check drawing.dxf`.
//
//   bytes ──tags (ASCII, or binary after its sentinel)──▶ HEADER ($INSUNITS, $ACADVER),
//         BLOCKS (definitions), ENTITIES (model space) ──▶ elements (INSERTs expanded, curves
//         fitted with biarcs) ──chain (geometry/chain.h)──▶ contours
//
// LINE, ARC, CIRCLE, LWPOLYLINE and POLYLINE/VERTEX (bulges: the bulge belongs to the segment that
// starts at its vertex), SPLINE (NURBS from control points, knots and weights; or a curve through
// its fit points), ELLIPSE (arcs too), INSERT (nested, scaled, rotated, mirrored, arrays). Entities
// in an object coordinate system whose extrusion is (0, 0, -1) are mirrored into the world plane.
// What carries no contour (TEXT, DIMENSION, HATCH, POINT ...) is counted as skipped.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"
#include "kerf/geometry/biarc.h"
#include "kerf/geometry/chain.h"
#include "kerf/geometry/segment.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

/// The sentinel that starts a binary DXF file.
inline constexpr std::string_view kBinaryDxfSentinel{"AutoCAD Binary DXF\r\n\x1a\0", 22};

/// A file is a DXF: the binary sentinel, or a first group `0 SECTION` (after `999` comments).
bool looksLikeDxf(std::string_view text);

struct DxfOptions {
  double curveTolerance = 0.001;  ///< mm: SPLINE, ELLIPSE and non-uniformly scaled arcs as biarcs
  /// mm per drawing unit; 0: as the file's $INSUNITS says (the default). A file with no $INSUNITS,
  /// or 0 (unitless), is read in mm [assumption: every unitless drawing in ../shared/realworld/dxf
  /// is drawn in mm — the R12 heart `cnc3-Herz-16.45x13.5` is 16.45 x 13.5 units; `--dxf-units
  /// mm|in` overrides].
  double unitToMm = 0.0;
  std::size_t maxElements = 5'000'000;  ///< refuse past this many lines and arcs (nested INSERT arrays)
  int maxInsertDepth = 16;
  /// Entity visits through INSERTs (copies of copies, arrays, those that add nothing included),
  /// counted before each INSERT expands: past it the drawing is refused (K0122).
  std::size_t maxVisits = 20'000'000;
};

struct DrawingElement {
  geometry::Segment segment;
  std::string entity;  ///< LINE, ARC, LWPOLYLINE ...
  std::string layer;
  std::uint32_t where = 0;  ///< ASCII: the 1-based line of the entity's `0` group; binary: its byte offset
  SourceSpan span;          ///< ASCII: the entity's type name; binary: empty
};

/// A curve read by readCurve (read_curve.h): how its biarcs came out.
struct FittedCurve {
  bool points = false;                     ///< a point list (else a parametric curve)
  double tolerance = 0.0;                  ///< mm, asked for
  double t0 = 0.0, t1 = 0.0;               ///< the parameter range (a point list: 0 to 1)
  std::vector<geometry::BiarcSpan> spans;  ///< nodes t0 < t1 and each span's sampled error
  double maxError = 0.0;                   ///< mm
};

struct Drawing {
  std::optional<FittedCurve> curve;  ///< set for a curve (read_curve.h), not for a DXF file
  std::string version;               ///< $ACADVER: AC1009 (R12) ... AC1032
  bool binary = false;
  int insUnits = 0;       ///< $INSUNITS as written (0: unitless or absent)
  double unitToMm = 1.0;  ///< the scale applied
  /// Model-space entities by type, as written (an INSERT counts once; VERTEX and SEQEND belong to
  /// their POLYLINE): what ezdxf's modelspace() lists.
  std::map<std::string, std::size_t> entities;
  std::map<std::string, std::size_t> skipped;  ///< of those, the ones that carry no contour
  std::vector<DrawingElement> elements;        ///< lines and arcs in mm, INSERTs expanded
  bool ok = false;                             ///< false: the file could not be read (diagnostics say why)
};

/// A drawing read (DXF): its elements and the contours they chain into (geometry/chain.h).
struct DrawingResult {
  Drawing drawing;
  std::vector<geometry::Chain> contours;
  /// Per contour, how many others enclose it (geometry::nestingDepths), made with the contours:
  /// the side each is cut on and the order they are cut in follow from it.
  std::vector<int> depth;
};

/// Reads a DXF file (ASCII or binary). Errors name the line (binary: the byte offset) and the
/// group code; the reader never throws on bad input.
Drawing readDxf(const SourceFile& source, const DxfOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
