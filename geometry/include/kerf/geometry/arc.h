// Arc construction from the words of an NC block: radius form (R) and centre form (I J).
//
// Tolerances follow LinuxCNC's interpreter (interp_internal.hh / interp_arc.cc), so Kerf accepts
// and refuses the same arcs a real controller does. Failures are values (ArcStatus), never
// exceptions: the converter turns them into diagnostics.
#pragma once

#include "kerf/geometry/segment.h"

namespace kerf::geometry {

/// Arc acceptance limits, in mm. Defaults are LinuxCNC's metric constants.
struct ArcTolerance {
  /// R form: how far |R| may fall short of half the chord (and the smallest radius accepted).
  /// LinuxCNC RADIUS_TOLERANCE_MM = 0.00005 in.
  double radius = 0.00005 * 25.4;
  /// Centre form: |end radius - start radius| accepted outright (CENTER_ARC_RADIUS_TOLERANCE_MM).
  double centreAbsolute = 2.0 * 0.01 * std::numbers::sqrt2;
  /// Centre form: between 1x and 100x centreAbsolute the difference is still accepted when it
  /// is no more than this fraction of the radius (SPIRAL_RELATIVE_TOLERANCE).
  double centreRelative = 0.001;

  /// The same limits for a program in inches (LinuxCNC's inch constants, converted to mm).
  static ArcTolerance forInch();
};

enum class ArcStatus : std::uint8_t {
  Ok,
  ZeroRadius,            ///< radius below ArcTolerance::radius
  RadiusTooSmall,        ///< R form: |R| < half the chord beyond the tolerance
  FullCircleWithRadius,  ///< R form with end == start: a full circle needs I J
  EndOffCircle,          ///< centre form: end radius differs from start radius beyond tolerance
};

struct ArcBuild {
  ArcStatus status = ArcStatus::Ok;
  Segment arc;               ///< valid when status == Ok
  double halfChord = 0.0;    ///< R form: half the start-end distance
  double radiusError = 0.0;  ///< centre form: |end - centre| - |start - centre| (signed)
};

/// R form. Positive R takes the arc of at most 180 degrees, negative R the longer one.
/// When |R| is short of half the chord by no more than tol.radius, the arc is the half circle.
ArcBuild arcFromRadius(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir,
                       const ArcTolerance& tol = {});

/// The seed paper's formulas (1) and (2) for the centre of an R arc, written as printed, with its
/// sign factor zn (G2: zn = +1 for R > 0, -1 for R < 0; G3: the opposite). Kept for teaching and
/// as an independent cross-check of arcFromRadius; returns NaN where the formulas have no real
/// value (chord longer than the diameter, or start == end).
Vec2 seedCentreFromRadius(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir);

/// Formulas (1) and (2) with the sign restored under their square roots: the printed
/// sqrt((Yp - Yk)^2 * D) and sqrt((Xp - Xk)^2 * D) become (Yp - Yk) sqrt(D) and (Xp - Xk) sqrt(D).
/// As printed, the formulas give the right centre only when Xp > Xk and Yp > Yk (the mirror
/// centre when both are smaller, a wrong point otherwise); with the signs restored they agree
/// with arcFromRadius everywhere (tests/unit/arc_test.cpp, docs/geometry.md).
Vec2 seedCentreFromRadiusSigned(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir);

/// The seed's sign factor zn for a direction and signed radius.
int seedSignFactor(ArcDirection dir, double signedRadius);

/// Whether an arc about `centre` from start to end is accepted (Ok, ZeroRadius or EndOffCircle),
/// with the signed radius error |end - centre| - |start - centre| when asked: arcFromCentre's
/// verdict without building the arc.
ArcStatus centreVerdict(const Vec2& start, const Vec2& end, const Vec2& centre, const ArcTolerance& tol = {},
                        double* radiusError = nullptr);

/// Centre form: the centre is given (already resolved from I J by the caller's convention).
/// end == start gives a full circle.
ArcBuild arcFromCentre(const Vec2& start, const Vec2& end, const Vec2& centre, ArcDirection dir,
                       const ArcTolerance& tol = {});

}  // namespace kerf::geometry
