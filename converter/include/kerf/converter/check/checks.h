// Geometric checks of a Toolpath: findings reported as diagnostics with a move and a point.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"

#include <optional>

namespace kerf::converter {

struct CheckOptions {
  double tolerance = 1e-6;  ///< mm: points closer than this coincide
  std::size_t maxContacts = 64;
  double maxTaperDegrees = 30.0;   ///< --max-taper: the machine's largest wire slope
  std::optional<double> uvRange;   ///< --uv-range: largest |upper - lower| per axis, mm
  int surfaceLevels = 16;          ///< sections of the surface tested: z at k/levels, 0 < k < levels
  double sectionTolerance = 5e-3;  ///< mm: chord tolerance of sections that are not lines or arcs
  /// Pieces of one section at most, counted before any is made; past it every polyline patch gets
  /// its share, coarser than sectionTolerance, and a note says so (K0657).
  std::size_t sectionBudget = 100'000;
};

struct SurfaceMeasures;

/// Runs the 2-axis checks on the cut moves (rapids are not cut):
///  - K0601/K0602/K0603 the cut path crosses, touches or overlaps itself (exact on lines and arcs);
///    K0604 (note) the lead-out retraces the lead-in;
///  - K0605 the cut path never closes a loop;  K0606 nothing is cut;
///  - K0607 a rapid between cuts (a point-driven machine would cut along it).
/// and on a taper program (Toolpath::upper) the same contour checks on the upper plane, then:
///  - K0655 one contour closes a loop and the other does not;
///  - K0650 the wire slope exceeds maxTaperDegrees (exact for line pairs, sampled otherwise);
///  - K0656 |upper - lower| exceeds uvRange;
///  - K0653 a patch twists: the upper direction of travel turns more than 90 degrees from the
///    lower one (exact: tangent angles are linear in t);
///  - K0651 two patches that are not neighbours meet, K0652 generators of one patch or of
///    neighbouring patches cross, K0654 neighbouring patches fold over each other: found on
///    surfaceLevels - 1 horizontal sections, each tested exactly (docs/taper.md).
/// When some contour has several passes (structure/passes.h), the cut-path checks run on each pass
/// alone, and K0605 is raised per contour that its passes do not cut free.
/// measures, when given, are measureSurface(toolpath), and structure findStructure(toolpath,
/// options.tolerance) (so `kerf check` computes them once).
void checkToolpath(const Toolpath& toolpath, const SourceFile* source, const CheckOptions& options, Diagnostics& diags,
                   const SurfaceMeasures* measures = nullptr, const Structure* structure = nullptr);

}  // namespace kerf::converter
