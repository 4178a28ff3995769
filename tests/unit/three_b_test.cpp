// 3B records, table-driven: lines in every quadrant, on every axis and at 45 degrees; arcs CW and
// CCW starting on each axis and inside each quadrant, over 1, 2, 3 and 4 quadrants, full circles.
// The expected G, Z and J are computed here independently of the writer: Z by the quadrant
// rules of FORMATS §4 written out as angle ranges, J by summing |d coordinate| over 200,000 steps
// of the arc. Each record is then read back, and must end where the arc ends.
#include "kerf/converter/formats/3b/read_3b.h"
#include "kerf/converter/formats/3b/write_3b.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>

namespace {

using namespace kerf::converter;
using kerf::geometry::ArcDirection;
using kerf::geometry::kPi;
using kerf::geometry::Segment;
using kerf::geometry::Vec2;

Toolpath pathOf(const Segment& s) {
  Toolpath t;
  Move m;
  m.kind = s.isArc() ? MoveKind::Arc : MoveKind::Line;
  m.lower = s;
  t.moves.push_back(m);
  t.blocks = 1;
  t.start = s.start;
  return t;
}

std::string firstRecord(const Toolpath& t) {
  Diagnostics d;
  ThreeBWriteOptions r;
  r.end = "";
  const auto out = writeThreeB(t, nullptr, r, d);
  EXPECT_TRUE(out.has_value());
  return out ? out->text.substr(0, out->text.find('\n')) : std::string();
}

Vec2 readBack(const std::string& record, const Vec2& start) {
  const SourceFile src("t.3b", record + "\nDD\n");
  Diagnostics d;
  const Toolpath t = readThreeB(src, ThreeBOptions{start}, d);
  EXPECT_EQ(d.errorCount(), 0u) << record;
  EXPECT_EQ(t.moves.size(), 1u) << record;
  return t.moves.empty() ? start : t.moves.back().lower.end;
}

/// Quadrant of a direction for a line end: on the axes +X 1, +Y 2, -X 3, -Y 4.
int lineZ(long dx, long dy) {
  if (dy == 0) return dx > 0 ? 1 : 3;
  if (dx == 0) return dy > 0 ? 2 : 4;
  return dx > 0 ? (dy > 0 ? 1 : 4) : (dy > 0 ? 2 : 3);
}

/// An arc's quadrant by the angle of its start (degrees in [0, 360)): counter-clockwise the
/// quadrant [90(k-1), 90k), clockwise (90(k-1), 90k].
int arcZ(double deg, bool ccw) {
  if (ccw) return static_cast<int>(std::floor(deg / 90.0)) % 4 + 1;
  const int k = static_cast<int>(std::ceil(deg / 90.0));
  return k == 0 ? 4 : k;
}

TEST(three_b_test, lines_in_every_quadrant_on_every_axis_and_at_45_degrees) {
  const long cases[][2] = {{5000, 0},      {0, 5000},     {-5000, 0},     {0, -5000},    {3000, 1000},   {-3000, 1000},
                           {-3000, -1000}, {3000, -1000}, {1000, 3000},   {-1000, 3000}, {-1000, -3000}, {1000, -3000},
                           {2000, 2000},   {-2000, 2000}, {-2000, -2000}, {2000, -2000}};
  for (const auto& c : cases) {
    const long dx = c[0], dy = c[1];
    const Vec2 start(1.0, 2.0), end(1.0 + static_cast<double>(dx) / 1000.0, 2.0 + static_cast<double>(dy) / 1000.0);
    const std::string rec = firstRecord(pathOf(Segment::line(start, end)));
    const int q = lineZ(dx, dy);
    const bool gy = std::labs(dy) > std::labs(dx) || (std::labs(dy) == std::labs(dx) && (q == 1 || q == 3));
    // On an axis x = y = 0 and J is the length (seed 004).
    const bool onAxis = dx == 0 || dy == 0;
    char want[96];
    std::snprintf(want, sizeof want, "B%ld B%ld B%ld G%c L%d", onAxis ? 0 : std::labs(dx), onAxis ? 0 : std::labs(dy),
                  gy ? std::labs(dy) : std::labs(dx), gy ? 'Y' : 'X', q);
    EXPECT_EQ(rec, want) << dx << "," << dy;
    EXPECT_LE((readBack(rec, start) - end).norm(), 1e-9) << rec;
  }
}

TEST(three_b_test, arcs_cw_and_ccw_over_one_to_four_quadrants_and_full_circles) {
  const double r = 10.0;  // mm
  int n = 0;
  for (const bool ccw : {true, false})
    for (const double a0 : {0.0, 90.0, 180.0, 270.0, 30.0, 120.0, 210.0, 300.0})
      for (const double sweep : {60.0, 150.0, 240.0, 330.0, 360.0}) {
        const double a1 = a0 + (ccw ? sweep : -sweep);
        const Vec2 centre(3.0, -4.0);
        auto at = [&](double deg) {
          const double a = deg * kPi / 180.0;
          return Vec2(centre.x() + r * std::cos(a), centre.y() + r * std::sin(a));
        };
        // Ends on the µm grid, as the writer rounds them.
        auto grid = [](const Vec2& p) {
          return Vec2(std::round(p.x() * 1000) / 1000, std::round(p.y() * 1000) / 1000);
        };
        const Vec2 s = grid(at(a0)), e = sweep == 360.0 ? s : grid(at(a1));
        const Segment arc = Segment::arc(s, e, centre, ccw ? ArcDirection::CounterClockwise : ArcDirection::Clockwise);
        const std::string rec = firstRecord(pathOf(arc));
        // Independent expectation.
        const Vec2 sr = (s - centre) * 1000.0, er = (e - centre) * 1000.0;
        const int z = arcZ(std::fmod(std::atan2(sr.y(), sr.x()) * 180.0 / kPi + 360.0, 360.0), ccw);
        const bool gy = std::abs(er.x()) > std::abs(er.y());
        double j = 0.0;
        const int steps = 200000;
        const double rr = sr.norm(), b0 = std::atan2(sr.y(), sr.x());
        const double total = (ccw ? 1 : -1) * sweep * kPi / 180.0;
        double prev = gy ? sr.y() : sr.x();
        for (int k = 1; k <= steps; ++k) {
          const double b = b0 + total * k / steps;
          const double v = k == steps ? (gy ? er.y() : er.x()) : (gy ? rr * std::sin(b) : rr * std::cos(b));
          j += std::abs(v - prev);
          prev = v;
        }
        std::smatch m;
        ASSERT_TRUE(std::regex_match(rec, m, std::regex(R"(B(\d+) B(\d+) B(\d+) G([XY]) ([SN])R(\d))"))) << rec;
        SCOPED_TRACE(rec + " (start " + std::to_string(a0) + " sweep " + std::to_string(sweep) +
                     (ccw ? " ccw)" : " cw)"));
        EXPECT_EQ(std::stol(m[1]), std::lround(std::abs(sr.x())));
        EXPECT_EQ(std::stol(m[2]), std::lround(std::abs(sr.y())));
        EXPECT_NEAR(std::stod(m[3]), j, 1.0);  // J rounded to the µm; the sum is exact to 1e-3 µm
        EXPECT_EQ(m[4].str(), gy ? "Y" : "X");
        EXPECT_EQ(m[5].str(), ccw ? "N" : "S");
        EXPECT_EQ(std::stoi(m[6]), z);
        EXPECT_LE((readBack(rec, s) - e).norm(), 1.5e-3);
        ++n;
      }
  EXPECT_EQ(n, 80);
}

}  // namespace
