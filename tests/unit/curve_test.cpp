// Curves as drawings (converter/formats/curve/read_curve.h): expressions through muparser and point lists, fitted with
// biarcs; their errors at the line and column of what is wrong.
#include "kerf/converter/formats/curve/read_curve.h"

#include "kerf/geometry/chain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

using namespace kerf::converter;

namespace {

struct Read {
  Drawing drawing;
  std::string firstError;  ///< "LINE:COL: message"
};

Read readCurveText(const std::string& text, double tolerance = 0.001) {
  const SourceFile src("c.curve", text);
  Diagnostics diags(100);
  CurveOptions o;
  o.tolerance = tolerance;
  Read r{readCurve(src, o, diags), {}};
  for (const Diagnostic& d : diags.all())
    if (d.severity == Severity::Error) {
      if (d.span.isWholeFile()) {
        r.firstError = "file: " + d.message;
      } else {
        const SourceLocation l = src.locate(d.span.offset);
        r.firstError = std::to_string(l.line) + ":" + std::to_string(l.column) + ": " + d.message;
      }
      break;
    }
  return r;
}

}  // namespace

TEST(curve_test, a_circle_from_its_expressions_is_one_closed_contour_within_the_tolerance) {
  const Read r = readCurveText("# a circle\nx = 7*cos(t)\ny = 7*sin(t)\nt = 0 : 2*pi\n");
  ASSERT_TRUE(r.firstError.empty()) << r.firstError;
  ASSERT_TRUE(r.drawing.ok);
  ASSERT_TRUE(r.drawing.curve);
  EXPECT_FALSE(r.drawing.curve->points);
  EXPECT_NEAR(r.drawing.curve->t1, 2 * std::numbers::pi, 1e-15);
  EXPECT_LE(r.drawing.curve->maxError, 0.001);
  EXPECT_EQ(r.drawing.entities.at("CURVE"), 1u);
  std::vector<kerf::geometry::Segment> segs;
  for (const DrawingElement& e : r.drawing.elements) {
    segs.push_back(e.segment);
    EXPECT_EQ(e.where, 2u);  // the line of x =
    // Every arc lies on the circle within the tolerance: its middle is 7 mm from the origin.
    EXPECT_NEAR(e.segment.pointAt(0.5).norm(), 7.0, 0.001);
  }
  const auto chains = kerf::geometry::chainSegments(segs);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_TRUE(chains[0].closed);
  EXPECT_NEAR(kerf::geometry::signedArea(chains[0].path), std::numbers::pi * 49, 0.05);
}

TEST(curve_test, statements_may_share_a_line_and_the_range_takes_expressions) {
  const Read r = readCurveText("x = t; y = t^2 ; t = -1 : sqrt(4)/2");
  ASSERT_TRUE(r.firstError.empty()) << r.firstError;
  EXPECT_DOUBLE_EQ(r.drawing.curve->t0, -1.0);
  EXPECT_DOUBLE_EQ(r.drawing.curve->t1, 1.0);
  EXPECT_NEAR((r.drawing.elements.front().segment.start - kerf::geometry::Vec2(-1, 1)).norm(), 0, 1e-12);
  EXPECT_NEAR((r.drawing.elements.back().segment.end - kerf::geometry::Vec2(1, 1)).norm(), 0, 1e-9);
}

TEST(curve_test, a_point_list_becomes_a_smooth_curve_through_its_points) {
  std::string text = "points\n";
  for (int k = 0; k <= 12; ++k) {
    const double a = std::numbers::pi * k / 12;
    text += std::to_string(10 * std::cos(a)) + ", " + std::to_string(10 * std::sin(a)) + "\n";
  }
  const Read r = readCurveText(text);
  ASSERT_TRUE(r.firstError.empty()) << r.firstError;
  ASSERT_TRUE(r.drawing.curve && r.drawing.curve->points);
  EXPECT_EQ(r.drawing.entities.at("POINTS"), 1u);
  // Through the points (to the 6 decimals they were written with), near the half circle between.
  for (const DrawingElement& e : r.drawing.elements) EXPECT_NEAR(e.segment.pointAt(0.5).norm(), 10.0, 0.02);
}

TEST(curve_test, errors_name_the_line_and_column) {
  EXPECT_EQ(readCurveText("x = t\ny = sin(t\nt = 0:1").firstError, "2:9: y: Missing parenthesis");
  EXPECT_EQ(readCurveText("x = t\ny = foo(t)\nt = 0:1").firstError.substr(0, 5), "2:5: ");
  EXPECT_EQ(readCurveText("x = t\ny = 1/t\nt = 0:1").firstError, "2:5: y is not a finite number at t = 0.000000");
  EXPECT_EQ(readCurveText("x = t\ny = t\nt = 1:1").firstError,
            "3:1: the range 1.000000 : 1.000000 is empty: FROM must be below TO");
  EXPECT_EQ(readCurveText("x = t\ny = t\nt = 0 .. 1").firstError, "3:1: the range is 't = FROM : TO', with a colon");
  EXPECT_EQ(readCurveText("x = t\nz = t\nt = 0:1").firstError,
            "2:1: a curve statement is 'x = EXPR', 'y = EXPR' or 't = FROM : TO', not 'z = t'");
  EXPECT_EQ(readCurveText("x = t\nx = 2*t\ny = t\nt = 0:1").firstError, "2:1: 'x' is given twice");
  EXPECT_EQ(readCurveText("x = t\nt = 0:1").firstError.rfind("file: the curve has no 'y = EXPR'", 0), 0u);
  EXPECT_EQ(readCurveText("points\n1 2\n3 x").firstError, "3:1: a point is two numbers, X Y or X, Y (mm), not '3 x'");
  EXPECT_EQ(readCurveText("points\n1 2\n1 2").firstError, "1:1: a point list needs at least two distinct points");
}

TEST(curve_test, only_curve_statements_look_like_a_curve) {
  EXPECT_TRUE(looksLikeCurve("# involute\nx = 10*cos(t)"));
  EXPECT_TRUE(looksLikeCurve("points\n0 0\n1 1"));
  EXPECT_FALSE(looksLikeCurve("G01 X10 Y5\nM02"));
  EXPECT_FALSE(looksLikeCurve("#1 = 5\nG01 X#1"));  // a LinuxCNC parameter is a comment here, then G-code
  EXPECT_FALSE(looksLikeCurve("B1000B0B1000GXL1"));
}
