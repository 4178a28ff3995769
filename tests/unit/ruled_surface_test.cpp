// The ruled surface: exact evaluation, slope, area, twist, folds, and the mesh.
#include "kerf/geometry/ruled_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace {

using namespace kerf::geometry;

TEST(ruled_surface_test, slope_matches_the_closed_form_to_1e9_degrees) {
  // A constant offset o over a height h: slope = atan(o / h), along the whole patch.
  for (const double o : {0.05, 0.5, 1.0, 3.3, 11.0}) {
    for (const double h : {5.0, 20.0, 137.0}) {
      const Planes planes{0.0, h};
      const Segment lo = Segment::line({0, 0}, {10, 3});
      const Segment up = Segment::line({0 + o, 0}, {10 + o, 3});
      const double expect = std::atan(o / h) * kDegreesPerRadian;
      for (double t : {0.0, 0.3, 1.0}) EXPECT_NEAR(slopeAt(lo, up, planes, t) * kDegreesPerRadian, expect, 1e-9);
      const PatchMeasures m = measurePatch(lo, up, planes);
      EXPECT_TRUE(m.exact);
      EXPECT_NEAR(m.maxSlope.value * kDegreesPerRadian, expect, 1e-9);
      EXPECT_NEAR(m.minSlope.value * kDegreesPerRadian, expect, 1e-9);
      // Concentric arcs r and r - o: the same slope, found by sampling and refinement.
      const Segment la = Segment::arc({20, 0}, {0, 20}, {0, 0}, ArcDirection::CounterClockwise);
      const Segment ua = Segment::arc({20 - o, 0}, {0, 20 - o}, {0, 0}, ArcDirection::CounterClockwise);
      const PatchMeasures ma = measurePatch(la, ua, planes);
      EXPECT_NEAR(ma.maxSlope.value * kDegreesPerRadian, expect, 1e-9);
      EXPECT_NEAR(ma.minSlope.value * kDegreesPerRadian, expect, 1e-9);
    }
  }
}

TEST(ruled_surface_test, refined_extremes_of_arc_patches_match_a_dense_search) {
  // Arc with line, arcs of different sweeps and centres: the extremes lie between the 65 samples.
  // The refined maximum is at least every one of 200,001 dense samples, and no more than the
  // largest of them plus what lies between two of them.
  const Planes planes{0.0, 15.0};
  const Segment arcA = Segment::arc({10, 0}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment arcB = Segment::arc({12, 1}, {-7, 3}, {2.5, 4.0}, ArcDirection::CounterClockwise);
  const Segment arcC = Segment::arc({9, -1}, {-11, 0.5}, {-0.6, 8.0}, ArcDirection::Clockwise);
  const Segment line = Segment::line({11, 2}, {-9, -1});
  const std::pair<Segment, Segment> pairs[] = {{arcA, line}, {line, arcA}, {arcA, arcB}, {arcB, arcC}, {arcC, arcA}};
  for (const auto& [lo, up] : pairs) {
    const PatchMeasures m = measurePatch(lo, up, planes);
    EXPECT_FALSE(m.exact);
    double big = 0, small = 1e300, bx = 0, by = 0;
    constexpr int kDense = 200000;
    for (int i = 0; i <= kDense; ++i) {
      const double t = static_cast<double>(i) / kDense;
      const Vec2 o = up.pointAt(t) - lo.pointAt(t);
      big = std::max(big, o.norm());
      small = std::min(small, o.norm());
      bx = std::max(bx, std::abs(o.x()));
      by = std::max(by, std::abs(o.y()));
    }
    const double maxSlope = std::atan2(big, planes.height()), minSlope = std::atan2(small, planes.height());
    EXPECT_GE(m.maxSlope.value, maxSlope - 1e-15);
    EXPECT_LE(m.maxSlope.value, maxSlope + 1e-9);
    EXPECT_LE(m.minSlope.value, minSlope + 1e-15);
    // Where the contours nearly cross, |o| has a corner at its minimum: it can lie below the dense
    // samples by up to half a step times |o'| (at most 100 mm per unit t here).
    EXPECT_GE(m.minSlope.value, minSlope - 100.0 * 0.5 / kDense / planes.height());
    EXPECT_GE(m.maxOffsetX.value, bx - 1e-12);
    EXPECT_LE(m.maxOffsetX.value, bx + 1e-8);
    EXPECT_GE(m.maxOffsetY.value, by - 1e-12);
    EXPECT_LE(m.maxOffsetY.value, by + 1e-8);
    // The t reported is where the value is.
    EXPECT_NEAR(std::atan2((up.pointAt(m.maxSlope.t) - lo.pointAt(m.maxSlope.t)).norm(), planes.height()),
                m.maxSlope.value, 1e-15);
  }
}

TEST(ruled_surface_test, line_pair_extremes_are_exact) {
  // Offset (0,-2) at t = 0 and (0,2) at t = 1: vertical in the middle, atan(2/10) at the ends.
  const Planes planes{0.0, 10.0};
  const PatchMeasures m = measurePatch(Segment::line({0, 2}, {10, -2}), Segment::line({0, 0}, {10, 0}), planes);
  EXPECT_NEAR(m.minSlope.value, 0.0, 1e-15);
  EXPECT_NEAR(m.minSlope.t, 0.5, 1e-15);
  EXPECT_NEAR(m.maxSlope.value, std::atan(0.2), 1e-15);
  EXPECT_NEAR(m.maxOffsetY.value, 2.0, 1e-15);
}

TEST(ruled_surface_test, area_of_a_frustum_and_of_a_wall) {
  const Planes planes{0.0, 20.0};
  // A wall: 10 x 20.
  EXPECT_NEAR(patchArea(Segment::line({0, 0}, {10, 0}), Segment::line({0, 0}, {10, 0}), planes), 200.0, 1e-9);
  // A cone frustum, radii 10 and 8: lateral area pi (r1 + r2) slant, per quarter.
  const Segment lo = Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment up = Segment::arc({8, 0}, {0, 8}, {0, 0}, ArcDirection::CounterClockwise);
  const double slant = std::hypot(2.0, 20.0);
  EXPECT_NEAR(patchArea(lo, up, planes), kPi * 18.0 * slant / 4.0, 1e-9 * 200);
}

TEST(ruled_surface_test, twist_is_found_exactly_and_its_near_miss_is_not) {
  const Segment lo = Segment::line({0, 0}, {10, 0});
  auto rotated = [](double deg) {
    const Vec2 d = 10.0 * direction(deg / kDegreesPerRadian);
    return Segment::line({0, 5}, Vec2(Vec2(0, 5) + d));
  };
  EXPECT_NEAR(measureTwist(lo, rotated(89.0)).maxAngle * kDegreesPerRadian, 89.0, 1e-9);
  EXPECT_NEAR(measureTwist(lo, rotated(91.0)).maxAngle * kDegreesPerRadian, 91.0, 1e-9);
  EXPECT_NEAR(measureTwist(lo, rotated(180.0)).maxAngle * kDegreesPerRadian, 180.0, 1e-9);
  // An arc's tangent turns linearly: a half circle against a line turns from 90 to -90 degrees.
  const Segment half = Segment::arc({10, 0}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const TwistMeasure tw = measureTwist(Segment::line({10, 0}, {-10, 0}), half);
  EXPECT_NEAR(tw.maxAngle * kDegreesPerRadian, 90.0, 1e-9);
  // A point has no direction.
  EXPECT_FALSE(measureTwist(lo, Segment::line({1, 1}, {1, 1})).defined);
}

TEST(ruled_surface_test, fold_at_a_joint_is_the_root_of_its_quadratic) {
  // The corner (10,0): below it turns 90 degrees, above it turns back over the first side; half
  // way up the second side runs exactly back along the first.
  const Segment l1 = Segment::line({0, 0}, {10, 0}), u1 = Segment::line({0, 0}, {10, 0});
  const Segment l2 = Segment::line({10, 0}, {10, 10}), u2 = Segment::line({10, 0}, {0, -10});
  const auto s = foldAtJoint(l1, u1, l2, u2);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 0.5, 1e-12);
  // Near miss: the second side above turns away (through 0, not 180 degrees).
  EXPECT_FALSE(foldAtJoint(l1, u1, l2, Segment::line({10, 0}, {20, -1})).has_value());
  // A corner that is already straight below and turns only one way above never folds.
  EXPECT_FALSE(foldAtJoint(l1, u1, Segment::line({10, 0}, {20, 0}), Segment::line({10, 0}, {20, 5})).has_value());
}

TEST(ruled_surface_test, sections_of_lines_and_matching_arcs_are_exact) {
  std::vector<Segment> out;
  EXPECT_TRUE(appendSection(Segment::line({0, 0}, {10, 0}), Segment::line({2, 2}, {12, 2}), 0.25, 1e-3, out));
  EXPECT_NEAR((out.back().start - Vec2(0.5, 0.5)).norm(), 0, 1e-15);
  const Segment lo = Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment up = Segment::arc({8, 0}, {0, 8}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_TRUE(appendSection(lo, up, 0.5, 1e-3, out));
  EXPECT_NEAR(out.back().radius(), 9.0, 1e-12);
  // An arc with a line: a polyline, equal steps of t, each chord within the tolerance.
  out.clear();
  const Segment chordLine = Segment::line({8, 0}, {0, 8});
  EXPECT_FALSE(appendSection(lo, chordLine, 0.5, 1e-3, out));
  ASSERT_GT(out.size(), 2u);
  const double n = static_cast<double>(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double tMid = (static_cast<double>(k) + 0.5) / n;
    const Vec2 truth = 0.5 * lo.pointAt(tMid) + 0.5 * chordLine.pointAt(tMid);
    const Vec2 chordMid = 0.5 * (out[k].start + out[k].end);
    EXPECT_LE((truth - chordMid).norm(), 1e-3);
  }
  EXPECT_EQ(out.back().end, Vec2(0.5 * (lo.end + chordLine.end)));
}

/// Every edge (unordered) and how many triangles use it.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edgeUse(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> use;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      ++use[{a, b}];
    }
  return use;
}

/// The circle-under-square part: quarter arcs below, square sides above, 30 mm apart.
void circleUnderSquare(std::vector<Segment>& lo, std::vector<Segment>& up) {
  const Vec2 p[4] = {{10, 0}, {0, 10}, {-10, 0}, {0, -10}};
  for (int i = 0; i < 4; ++i) {
    lo.push_back(Segment::arc(p[i], p[(i + 1) % 4], {0, 0}, ArcDirection::CounterClockwise));
    up.push_back(Segment::line(p[i], p[(i + 1) % 4]));
  }
}

TEST(ruled_surface_test, closed_mesh_with_caps_is_watertight_and_oriented) {
  std::vector<Segment> lo, up;
  circleUnderSquare(lo, up);
  MeshOptions opt;
  opt.tolerance = 0.01;
  opt.lowerCap = opt.upperCap = true;
  const Mesh m = meshRuledSurface(lo, up, {0.0, 30.0}, opt);
  EXPECT_EQ(m.capsMade, 2u);
  for (const auto& [edge, n] : edgeUse(m)) EXPECT_EQ(n, 2) << edge.first << "-" << edge.second;
  // Oriented: every directed edge appears once.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, n] : directed) EXPECT_EQ(n, 1);
  // Without caps: the two contours are the only edges used once.
  const Mesh open = meshRuledSurface(lo, up, {0.0, 30.0}, {});
  std::size_t boundary = 0;
  for (const auto& [edge, n] : edgeUse(open)) {
    EXPECT_LE(n, 2);
    if (n == 1) {
      ++boundary;
      EXPECT_TRUE(std::abs(open.vertices[edge.first].z()) < 1e-12 ||
                  std::abs(open.vertices[edge.first].z() - 30) < 1e-12);
    }
  }
  EXPECT_GT(boundary, 8u);
}

/// Distance from p to triangle abc.
double pointTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0) {
    const Vec3 q = p - n * (n.dot(p - a) / nn);
    const double u = n.dot((c - b).cross(q - b)), v = n.dot((a - c).cross(q - c)), w = n.dot((b - a).cross(q - a));
    if (u >= 0 && v >= 0 && w >= 0) return (p - q).norm();
  }
  auto seg = [&](const Vec3& x, const Vec3& y) {
    const Vec3 d = y - x;
    const double t = d.squaredNorm() > 0 ? std::clamp(d.dot(p - x) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p - (x + t * d)).norm();
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

TEST(ruled_surface_test, mesh_stays_within_its_tolerance_of_the_exact_surface) {
  // A twisted patch (arc below, a line turned 60 degrees above) and the circle-under-square.
  std::vector<Segment> lo, up;
  circleUnderSquare(lo, up);
  lo.push_back(Segment::arc({30, 0}, {0, 30}, {0, 0}, ArcDirection::CounterClockwise));
  up.push_back(Segment::line({25, 5}, {10, 20}));
  for (const double tol : {0.05, 0.01}) {
    MeshOptions opt;
    opt.tolerance = tol;
    const Planes planes{0.0, 30.0};
    const Mesh m = meshRuledSurface(lo, up, planes, opt);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (std::size_t patch = 0; patch < lo.size(); ++patch) {
      for (int k = 0; k < 60; ++k) {
        const Vec3 p = surfacePoint(lo[patch], up[patch], planes, u(rng), u(rng));
        double best = 1e300;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
          if (m.trianglePatch[t] != patch) continue;
          const auto& tri = m.triangles[t];
          best = std::min(best, pointTriangle(p, m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]));
        }
        worst = std::max(worst, best);
      }
    }
    EXPECT_LE(worst, tol) << "tolerance " << tol;
    EXPECT_GT(worst, tol / 1000) << "a mesh that matches exactly here would not test anything";
  }
}

TEST(ruled_surface_test, normals_of_a_vertical_counter_clockwise_wall_point_outwards) {
  const Segment arc = Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise);
  const Vec3 n = surfaceNormal(arc, arc, {0.0, 10.0}, 0.5, 0.5);
  EXPECT_NEAR(n.dot(Vec3(std::sqrt(0.5), std::sqrt(0.5), 0)), 1.0, 1e-12);
}

}  // namespace

namespace {

// Each mesh vertex carries the slope of the generator it lies on, and a leaning patch gets at
// least minTaperPieces pieces, so the slope is sampled inside it.
TEST(ruled_surface_mesh_test, vertex_slope_is_the_generator_slope_and_leaning_patches_are_split) {
  using kerf::geometry::Segment;
  using kerf::geometry::Vec2;
  const Segment lower = Segment::line(Vec2(-10, -10), Vec2(10, -10));
  const Segment upper = Segment::line(Vec2(-8, -8), Vec2(8, -8));
  const kerf::geometry::Planes planes{0.0, 10.0};
  kerf::geometry::MeshOptions options;
  options.minTaperPieces = 8;
  const kerf::geometry::Mesh mesh =
      kerf::geometry::meshRuledSurface(std::span(&lower, 1), std::span(&upper, 1), planes, options);
  ASSERT_EQ(mesh.vertexSlope.size(), mesh.vertices.size());
  double least = 1e9;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    least = std::min(least, static_cast<double>(mesh.vertexSlope[v]));
  EXPECT_NEAR(least, std::atan(0.2), 1e-6);  // the generator at t = 1/2 is a vertex
  // A vertical patch is not split beyond what its tolerance needs: one piece, two triangles.
  const kerf::geometry::Mesh wall =
      kerf::geometry::meshRuledSurface(std::span(&lower, 1), std::span(&lower, 1), planes, options);
  EXPECT_EQ(wall.triangles.size(), 2u);
  for (float s : wall.vertexSlope) EXPECT_EQ(s, 0.0f);
  EXPECT_GE(mesh.triangles.size(), 16u);
}

}  // namespace

namespace {

// A huge twisted arc pair (the fuzzer's slow input: R 50 m against a turned line): the mesh
// counts its triangles before it makes vertices, so a small budget costs little memory.
TEST(ruled_surface_mesh_test, the_triangle_budget_is_counted_before_any_vertex_is_made) {
  using namespace kerf::geometry;
  std::vector<Segment> lo, up;
  for (int k = 0; k < 40; ++k) {
    const double x = 100000.0 * k;
    lo.push_back(Segment::arc({x, 0}, {x + 100000, 0}, {x + 50000, 100}, ArcDirection::Clockwise));
    up.push_back(Segment::line({x + 30000, 5000}, {x + 70000, -5000}));
  }
  const Planes planes{0.0, 50.0};
  MeshOptions opt;
  opt.tolerance = 0.1;
  const Mesh full = meshRuledSurface(std::span(lo).first(1), std::span(up).first(1), planes, opt);
  ASSERT_FALSE(full.truncated);
  ASSERT_GT(full.triangles.size(), 10000u) << "the case must be big enough to be cut short";
  for (const std::size_t budget : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, full.triangles.size() - 1}) {
    opt.maxTriangles = budget;
    const Mesh m = meshRuledSurface(lo, up, planes, opt);
    EXPECT_TRUE(m.truncated) << budget;
    EXPECT_LE(m.triangles.size(), budget);
    // Each generator brings at most kMaxMeshCuts + 1 vertices, and each kept cell two triangles.
    EXPECT_LE(m.vertices.size(), (budget / 2 + 2) * (kMaxMeshCuts + 1)) << budget;
  }
  opt.maxTriangles = full.triangles.size();
  const Mesh exact = meshRuledSurface(std::span(lo).first(1), std::span(up).first(1), planes, opt);
  EXPECT_FALSE(exact.truncated) << "a budget of exactly the mesh's triangles is enough";
  EXPECT_EQ(exact.triangles.size(), full.triangles.size());
}

}  // namespace
