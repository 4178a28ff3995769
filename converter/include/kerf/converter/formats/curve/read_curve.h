// Curves as drawings (seed 003, CAWEP §2; docs/cam.md, "Curves"): a parametric curve or a point
// list, fitted with biarcs (geometry/biarc.h), read as a drawing of one contour that every command
// takes — `kerf check --curve "x=…; y=…" --t A:B`, `kerf render`, `kerf cam`.
//
// The text (a `.curve` file, `--format curve`, or what --curve and --t make) is statements
// separated by newlines or `;`, `#` starting a comment:
//
//   x = 10*(cos(t) + t*sin(t))      # muparser expressions of the parameter t (Debian's
//   y = 10*(sin(t) - t*cos(t))      # libmuparser: sin cos tan exp ln sqrt abs ^ ..., pi)
//   t = 0 : 2                       # the range, two expressions
//
// or a point list: the word `points`, then one `X Y` (or `X, Y`) pair in mm per line — a smooth
// curve through them (an interpolating cubic spline), fitted the same way.
#pragma once

#include "kerf/converter/formats/dxf/read_dxf.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"

#include <cstddef>
#include <string_view>

namespace kerf::converter {

struct CurveOptions {
  double tolerance = 0.001;       ///< mm: the biarcs' largest distance from the curve
  std::size_t maxSpans = 100000;  ///< refuse a fit past this many spans
};

/// True when the text's first statement is `x =`, `y =`, `t =` or `points` (what --format auto
/// takes for a curve).
bool looksLikeCurve(std::string_view text);

/// Reads and fits the curve: a drawing whose elements are the biarcs (entity CURVE or POINTS),
/// with Drawing::curve saying how close they came. Errors (K0130: an expression that does not parse
/// or evaluate, a range that is empty, a point that is not two numbers; K0131: a fit that fails)
/// name the line and column; on error the drawing has no elements and ok is false.
Drawing readCurve(const SourceFile& source, const CurveOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
