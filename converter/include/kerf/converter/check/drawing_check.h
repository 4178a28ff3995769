// Does the program cut the drawing? The part edge a program cuts against the drawing's elements,
// element by element, both ways (issue 43, docs/drawing.md).
//
// The part edge: for each contour, the programmed moves along its last pass that is not a cut-off,
// and its cut-offs. A pass cut with G41/G42 gives its programmed contour; one cut with no offset in
// force is the wire-centre path, moved back by `wireOffset` when it is given (compared as written
// when not). The drawing: its lines and arcs in mm, moved by `origin` (the drawing's point at the
// program's origin). Every distance is certified to within the precision (geometry/deviation.h),
// not sampled.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/align.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::converter {

/// A drawing element as the comparison needs it (the checks come before the formats: the pipeline
/// makes these from the DXF reader's elements).
struct DrawnElement {
  geometry::Segment segment;  ///< mm, in the drawing's frame
  std::string entity;         ///< LINE, ARC, LWPOLYLINE ...
  std::uint32_t line = 0;     ///< the entity's line in the DXF (binary: its byte offset)
  SourceSpan span;            ///< the entity's type name in the DXF
};

struct DrawingCheckOptions {
  double tolerance = 0.005;  ///< mm [decided: a wire machine's positioning is a few µm]
  geometry::Vec2 origin{0, 0};
  std::string layer;        ///< --drawing-layer: only this layer's elements (empty: every layer)
  std::string upperLayer;   ///< --drawing-upper-layer: the upper plane's layer (empty: every layer)
  double precision = 1e-4;  ///< mm: how close to the true largest distance each figure is
  /// mm (--offset): a pass cut with no G41/G42 in force is the wire-centre path, and its part edge
  /// is that path moved back by this much. Nothing: such a pass is compared as written.
  std::optional<double> wireOffset;
  /// --side: the wire ran outside the outermost contours (true: a punch) or inside them (a die);
  /// contours inside those the other way. Nothing: each contour is moved back to the side whose
  /// edge lies nearer the drawing (said in a note).
  std::optional<bool> wireOutside;
  /// --align: the drawing is placed where it fits the part edge best (geometry/align.h), and the
  /// placement reported. Without it the drawing stays where `origin` puts it, and a placement is
  /// looked for only to name it when the drawing does not fit there.
  bool align = false;
  /// The part edge on the upper plane: the upper contour of the same moves (a taper program's;
  /// --drawing-upper). The drawing is then the upper plane's.
  bool upperPlane = false;
};

/// A drawing element against the part edge.
struct ElementDeviation {
  std::size_t element = 0;        ///< in Drawing::elements
  double deviation = 0.0;         ///< mm: its farthest point from the edge
  geometry::Vec2 at{0, 0};        ///< that point, in the program's frame
  std::size_t move = 0;           ///< the move of the edge nearest it
  std::uint32_t drawingLine = 0;  ///< the element's line in the DXF (binary: its byte offset)
  std::uint32_t blockLine = 0;    ///< that move's line in the program
};

/// A piece of the part edge against the drawing: a move as programmed, or a piece of a wire-centre
/// path moved back (then several pieces may come from one move).
struct EdgeDeviation {
  std::size_t move = 0;
  geometry::Segment segment;  ///< the piece, mm, in the program's frame
  double deviation = 0.0;     ///< mm: its farthest point from the drawing
  geometry::Vec2 at{0, 0};
};

struct DrawingComparison {
  std::string drawing;  ///< the DXF's name
  std::vector<ElementDeviation> elements;
  std::vector<EdgeDeviation> edge;
  double worst = 0.0;              ///< mm, both ways
  std::size_t outOfTolerance = 0;  ///< drawing elements off by more than the tolerance
  double tolerance = 0.0;
  /// The drawing's placement onto the program besides `origin`: --align's, or the one found to fit
  /// when it does not fit as placed (then the deviations are still those as placed).
  std::optional<geometry::Placement> placement;
  /// The drawing's elements in the program's frame, as compared (pictures draw them beside the part).
  std::vector<geometry::Segment> drawn;
  bool upper = false;  ///< the upper plane's comparison (--drawing-upper)
};

/// Compares and reports: an element off by more than the tolerance (K0630, at the nearest block;
/// a contour off by one distance all round is said once), a closed drawing contour that no
/// contour of the program follows (K0631, at its first entity), moves that cut what the drawing
/// does not have (K0632, one per run of such moves), how a wire-centre path was taken (K0633).
DrawingComparison compareWithDrawing(const Toolpath& toolpath, const Structure& structure,
                                     const std::vector<DrawnElement>& drawing, const DrawingCheckOptions& options,
                                     const SourceFile* program, const SourceFile* drawingSource, Diagnostics& diags);

}  // namespace kerf::converter
