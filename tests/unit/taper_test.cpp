// 4-axis taper: dialects, heights, pairing, and every check with a part that trips it and a
// near miss that must not; metamorphic reruns of the samples.
#include "kerf/converter/check/checks.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/interpret/analysis.h"
#include "kerf/converter/interpret/dialect.h"

#include "converter_support.h"
#include "kerf/converter/formats/emit.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

using namespace kerf::converter;
using kerf::geometry::Segment;
using kerf::geometry::Vec2;
using kerf::test::run;

std::set<Code> errorCodes(const Diagnostics& d) {
  std::set<Code> out;
  for (const auto& x : d.all())
    if (x.severity == Severity::Error) out.insert(x.code);
  return out;
}

std::unique_ptr<kerf::test::Run> check(const std::string& text, CheckOptions co = {}, InterpreterOptions io = {}) {
  auto r = run(text, io);
  checkToolpath(r->analysis.toolpath, r->source.get(), co, r->diags);
  return r;
}

/// xyuv-abs square 10 x 10 below; above, corner points given (U V after each X Y).
std::string xyuvSquare(const std::vector<Vec2>& upper, double thickness = 10.0) {
  const Vec2 lower[5] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
  std::ostringstream s;
  s << "M101 P" << thickness << "\nG92 X0 Y0 U" << upper[0].x() << " V" << upper[0].y() << "\n";
  for (int i = 1; i < 5; ++i)
    s << "G1 X" << lower[i].x() << " Y" << lower[i].y() << " G1 U" << upper[i].x() << " V" << upper[i].y() << "\n";
  s << "M2\n";
  return s.str();
}

std::vector<Vec2> shifted(double dx, double dy) {
  return {{dx, dy}, {10 + dx, dy}, {10 + dx, 10 + dy}, {dx, 10 + dy}, {dx, dy}};
}

// ---- dialects and heights -------------------------------------------------------------------

TEST(taper_test, every_dialect_parses_and_is_detected) {
  struct Case {
    const char* text;
    Dialect dialect;
  } cases[] = {
      {"M101 P20\nG92 X0 Y0 U0 V0\nG1 X5 Y0 G1 U5 V0\nG2 X10 Y5 I5 J0 G1 U10 V5\nM2\n", Dialect::XyuvAbs},
      {"G92 X0 Y0 I20. J0\nG1 X10 Y0 U-1 V0\nG3 X10 Y0 I-10 J0 U-1 V0 K0 L0\nM2\n", Dialect::XyuvRel},
      {"TN0 TP20.\nG141\nG01 X10. Y0 : G02 X10. Y0 I5. J0\nG140\nM02\n", Dialect::SodickColon},
      {"G92 X0 Y-5 I20.\nG51 A2.\nG01 X0 Y0\nX10.\nG50\nG01 Y-5.\nM02\n", Dialect::TaperAngle},
      {"G92 X0 Y-5 I20.\nG52 T2.\nG01 X0 Y0\nX10.\nG50\nG01 Y-5.\nM02\n", Dialect::TaperAngle},
  };
  for (const Case& c : cases) {
    auto r = run(c.text);
    EXPECT_EQ(r->path().dialect, c.dialect) << c.text;
    EXPECT_FALSE(r->diags.hasErrors()) << c.text << kerf::test::dump(r->diags);
    EXPECT_TRUE(r->hasCode(Code::DialectChosen));
    EXPECT_EQ(r->path().upper.size(), r->path().moves.size());
    EXPECT_TRUE(r->path().heights.known);
  }
}

TEST(taper_test, ambiguous_uv_is_an_error_until_the_dialect_is_given) {
  // |U - X| + |V - Y| = 3 against |U| + |V| = 5: the numbers decide nothing.
  const std::string text = "G92 X0 Y0 U0 V0\nG1 X1. Y1. U2. V3.\nM2\n";
  auto r = run(text);
  EXPECT_TRUE(r->hasCode(Code::DialectAmbiguous));
  InterpreterOptions io;
  io.thickness = 10.0;
  io.dialect = Dialect::XyuvAbs;
  auto a = run(text, io);
  EXPECT_FALSE(a->diags.hasErrors()) << kerf::test::dump(a->diags);
  EXPECT_NEAR(a->path().upper[0].end.x(), 2.0, 1e-12);
  io.dialect = Dialect::XyuvRel;
  auto rel = run(text, io);
  EXPECT_FALSE(rel->diags.hasErrors());
  EXPECT_NEAR(rel->path().upper[0].end.x(), 3.0, 1e-12);  // lower 1 + offset 2
  io.dialect = Dialect::Plain;
  EXPECT_TRUE(run(text, io)->hasCode(Code::WordNotInDialect));
}

TEST(taper_test, absolute_or_relative_uv_decided_by_the_numbers) {
  // U V that follow X Y are the upper contour itself; U V that stay small against X Y are the
  // deviation of the upper contour (docs/taper.md). The note names the numbers.
  auto abs = run("G92 X0 Y0 U0 V0\nG1 X10. Y0 U10.5 V0\nX10. Y10. U10.5 V9.5\nX0 Y0 U0 V0\nM2\n");
  EXPECT_EQ(abs->path().dialect, Dialect::XyuvAbs);
  auto rel = run("G92 X0 Y0 U0 V0\nG1 X10. Y0 U0.5 V0\nX10. Y10. U0.5 V-0.5\nX0 Y0 U0 V0\nM2\n");
  EXPECT_EQ(rel->path().dialect, Dialect::XyuvRel);
  for (const auto* r : {abs.get(), rel.get()}) {
    bool named = false;
    for (const auto& d : r->diags.all())
      named |= d.code == Code::DialectChosen && d.message.find("the numbers") != std::string::npos;
    EXPECT_TRUE(named) << kerf::test::dump(r->diags);
  }
  // Incremental programs compare the positions the increments reach: U V moving with X Y are absolute.
  EXPECT_EQ(run("G91\nG1 X10. U10. Y0 V0\nX0 Y10. U-0.5 V10.\nM2\n")->path().dialect, Dialect::XyuvAbs);
  // Issue 42: a hot-wire wing homed with G28, cut in G91, its tip 60 % of its root and swept 35 mm.
  // The increments alone (|dU - dX| against |dU|: 15.4 against 24.8) decide nothing; the positions
  // they reach (13.0 against 42.2) say U V are the tip's contour itself.
  auto wing =
      run("G21\nG28 X Y\nG28 U V\nG91\nG1 X20 Y10 U47 V16 F300\nG1 X100 Y0 U60 V0\nG1 X-20 Y8 U-12 V4.8\n"
          "G1 X-80 Y-8 U-48 V-4.8\nG1 X0 Y-10 U0 V-6\nM2\n");
  EXPECT_EQ(wing->path().dialect, Dialect::XyuvAbs) << kerf::test::dump(wing->diags);
  EXPECT_FALSE(wing->hasCode(Code::DialectAmbiguous));
}

TEST(taper_test, heights_come_from_options_first_then_the_program) {
  const std::string body = "G92 X0 Y0 U0 V0\nG1 X10 Y0 G1 U11 V0\nM2\n";
  EXPECT_TRUE(run("M100 P1 Q1\n" + body)->hasCode(Code::HeightsMissing));
  EXPECT_NEAR(run("M101 P12.5\n" + body)->path().heights.planes.upper, 12.5, 1e-12);
  EXPECT_NEAR(run("(AXIS,XY_Z_POS,2)\n(AXIS,UV_Z_POS,32)\nM100 P1 Q1\n" + body)->path().heights.planes.height(), 30,
              1e-12);
  InterpreterOptions io;
  io.upperZ = 40.0;
  EXPECT_NEAR(run("M101 P12.5\n" + body, io)->path().heights.planes.upper, 40.0, 1e-12);
  io.upperZ.reset();
  io.lowerZ = 5.0;
  io.thickness = 10.0;
  EXPECT_NEAR(run("M101 P12.5\n" + body, io)->path().heights.planes.upper, 15.0, 1e-12);
  // Sodick: TN the lower plane, TP the program plane (taken as the upper one here).
  auto s = run("TN5. TP25.\nG01 X1 Y0 : X1 Y0\nM02\n");
  EXPECT_NEAR(s->path().heights.planes.height(), 20.0, 1e-12);
  // NCVC: G92 I thickness, J program plane.
  auto n = run("G92 X0 Y-5 I30. J10.\nG51 T1.\nG01 X0 Y0\nG50\nG01 Y-5.\nM02\n");
  EXPECT_NEAR(n->path().heights.programZ, 10.0, 1e-12);
  EXPECT_NEAR(n->path().heights.planes.upper, 30.0, 1e-12);
}

TEST(taper_test, taper_angle_offsets_by_height_times_tangent) {
  // Lean left 2 degrees, 25 mm up: lines move 25 tan 2 to their left, arcs stay concentric,
  // corners are sharp, the start-up line starts vertical and the end line ends vertical.
  auto r = run("G92 X0 Y-5. I25.\nG51 A2.\nG01 X0 Y0\nX10.\nG03 X15. Y5. I0 J5.\nG01 Y10.\nG50\nG01 X20.\nM02\n");
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  const double d = 25.0 * std::tan(2.0 * kerf::geometry::kPi / 180.0);
  const auto& up = r->path().upper;
  EXPECT_NEAR(up[1].start.y(), d, 1e-12);
  EXPECT_NEAR(up[1].end.y(), d, 1e-12);
  EXPECT_NEAR((up[0].end - Vec2(-d, d)).norm(), 0.0, 1e-12);  // sharp corner of the start-up
  EXPECT_NEAR(up[2].radius(), 5.0 - d, 1e-12);                // concentric, left of CCW: smaller
  EXPECT_EQ(up[0].start, Vec2(0, -5));
  EXPECT_EQ(up.back().end, Vec2(20, 10));
  // On the arc the offset is square to the travel: exactly 2 degrees. At the sharp start-up
  // corner it is the diagonal, sqrt(2) times as far.
  const double toDeg = 180.0 / kerf::geometry::kPi;
  const auto measures = measureSurface(r->path());
  EXPECT_NEAR(measures.patches[2].minSlope.value * toDeg, 2.0, 1e-9);
  EXPECT_NEAR(measures.patches[2].maxSlope.value * toDeg, 2.0, 1e-9);
  EXPECT_NEAR(measures.patches[1].maxSlope.value * toDeg, std::atan(std::sqrt(2.0) * d / 25.0) * toDeg, 1e-9);
}

// ---- each check: a part that trips it and a near miss ----------------------------------------

TEST(taper_checks_test, slope_above_the_machine_limit) {
  const double limit = 10.0 * std::tan(30.0 * kerf::geometry::kPi / 180.0);  // 5.7735
  EXPECT_TRUE(errorCodes(check(xyuvSquare(shifted(limit + 0.001, 0)))->diags).count(Code::TaperTooSteep));
  EXPECT_FALSE(errorCodes(check(xyuvSquare(shifted(limit - 0.001, 0)))->diags).count(Code::TaperTooSteep));
  CheckOptions co;
  co.maxTaperDegrees = 20.0;
  EXPECT_TRUE(errorCodes(check(xyuvSquare(shifted(4.0, 0)), co)->diags).count(Code::TaperTooSteep));
}

TEST(taper_checks_test, angle_word_beyond_45_is_refused) {
  const std::string head = "G92 X0 Y-5. I10.\nG51 A";
  EXPECT_TRUE(run(head + "45.1\nG01 X0 Y0\nM02\n")->hasCode(Code::TaperAngleTooLarge));
  EXPECT_FALSE(run(head + "45.\nG01 X0 Y0\nM02\n")->hasCode(Code::TaperAngleTooLarge));
}

TEST(taper_checks_test, upper_contour_self_intersection) {
  const auto bow = check(xyuvSquare({{0, 0}, {10, 0}, {0, 10}, {10, 10}, {0, 0}}, 30.0));
  EXPECT_TRUE(errorCodes(bow->diags).count(Code::PathCrossesItself));
  const auto fine = check(xyuvSquare({{0, 0}, {10, 0}, {9, 10}, {1, 10}, {0, 0}}, 30.0));
  EXPECT_TRUE(errorCodes(fine->diags).empty()) << kerf::test::dump(fine->diags);
}

TEST(taper_checks_test, surface_meets_itself_between_simple_contours) {
  auto part = [](double px) {
    std::ostringstream s;
    s << "M101 P20\nG92 X0 Y0 U0 V0\nG1 X10 Y0 G1 U10 V8\nG1 X8 Y1 G1 U" << px
      << " V1\nG1 X2 Y3 G1 U-2 V4\nG1 X0 Y0 G1 U0 V0\nM2\n";
    return s.str();
  };
  EXPECT_TRUE(errorCodes(check(part(0.0))->diags).count(Code::SurfaceSelfIntersection));
  const auto near = check(part(6.0));
  EXPECT_FALSE(errorCodes(near->diags).count(Code::SurfaceSelfIntersection)) << kerf::test::dump(near->diags);
}

TEST(taper_checks_test, wire_crossing_and_twist) {
  auto one = [](const char* upperEnd) {
    return std::string("M101 P30\nG92 X0 Y0 U10 V0\nG1 X10 Y0 G1 ") + upperEnd + "\nM2\n";
  };
  // Upper runs exactly back: every generator passes through one point.
  EXPECT_TRUE(errorCodes(check(one("U0 V0"))->diags).count(Code::WireCrossing));
  // 91 degrees away: twisted; 89: fine.
  auto turned = [&](double deg) {
    const double a = deg * kerf::geometry::kPi / 180.0;
    std::ostringstream s;
    s << "U" << 10 + 10 * std::cos(a) << " V" << 10 * std::sin(a);
    return check(one(s.str().c_str()));
  };
  EXPECT_TRUE(errorCodes(turned(91)->diags).count(Code::PatchTwisted));
  const auto fine = turned(89);
  EXPECT_FALSE(errorCodes(fine->diags).count(Code::PatchTwisted));
  EXPECT_FALSE(errorCodes(fine->diags).count(Code::WireCrossing));
}

TEST(taper_checks_test, fold_between_neighbours) {
  auto part = [](const char* third) {
    return std::string("M101 P30\nG92 X0 Y0 U0 V0\nG1 X10 Y0 G1 U10 V0\nG1 X10 Y10 G1 ") + third +
           "\nG1 X0 Y10 G1 U-10 V0\nG1 X0 Y0 G1 U0 V0\nM2\n";
  };
  EXPECT_TRUE(errorCodes(check(part("U0 V-10"))->diags).count(Code::SurfaceFold));
  EXPECT_FALSE(errorCodes(check(part("U5 V5"))->diags).count(Code::SurfaceFold));
}

TEST(taper_checks_test, one_contour_closed_and_the_other_not) {
  auto open = xyuvSquare({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 3}});
  EXPECT_TRUE(errorCodes(check(open)->diags).count(Code::ClosureMismatch));
  EXPECT_FALSE(errorCodes(check(xyuvSquare(shifted(1, 1)))->diags).count(Code::ClosureMismatch));
}

TEST(taper_checks_test, uv_range) {
  CheckOptions co;
  co.uvRange = 2.0;
  EXPECT_TRUE(errorCodes(check(xyuvSquare(shifted(2.5, 0)), co)->diags).count(Code::UvOutOfRange));
  EXPECT_FALSE(errorCodes(check(xyuvSquare(shifted(1.5, 1.5)), co)->diags).count(Code::UvOutOfRange));
}

TEST(taper_checks_test, taper_started_or_ended_on_an_arc) {
  EXPECT_TRUE(run("G92 X10 Y0 I20.\nG52 A3.\nG03 X-10 Y0 I-10 J0\nM02\n")->hasCode(Code::TaperOnArc));
  EXPECT_TRUE(run("G92 X10 Y-5 I20.\nG52 A3.\nG01 X10 Y0\nG50\nG03 X-10 Y0 I-10 J0\nM02\n")->hasCode(Code::TaperOnArc));
  EXPECT_FALSE(run("G92 X10 Y-5 I20.\nG52 A3.\nG01 X10 Y0\nG03 X-10 Y0 I-10 J0\nG50\nG01 X-10 Y-5\nM02\n")
                   ->hasCode(Code::TaperOnArc));
}

TEST(taper_checks_test, sodick_block_without_upper_side_inside_g141) {
  EXPECT_TRUE(run("TP20.\nG141\nG01 X10 Y0 : X10 Y0\nG01 X10 Y10\nG140\nM02\n")->hasCode(Code::UpperSideMissing));
  EXPECT_FALSE(run("TP20.\nG141\nG01 X10 Y0 : X10 Y0\nG140\nG01 X10 Y10\nM02\n")->hasCode(Code::UpperSideMissing));
}

TEST(taper_checks_test, two_file_pairing_counts_moves) {
  SourceFile lo("lower.nc", "G01 X10 Y0\nX10 Y10\nX0 Y0\nM02\n");
  SourceFile up2("upper.nc", "G01 X11 Y0\nX0 Y0\nM02\n");
  SourceFile up3("upper.nc", "G01 X11 Y1\nX11 Y11\nX0 Y0\nM02\n");
  InterpreterOptions io;
  io.dialect = Dialect::Plain;
  io.thickness = 20.0;
  for (const SourceFile* up : {&up2, &up3}) {
    Diagnostics d;
    Analysis a = analyse(lo, io, d);
    const Analysis b = analyse(*up, io, d);
    pairUpper(a.toolpath, b.toolpath, &lo, up, d);
    EXPECT_EQ(errorCodes(d).count(Code::BlockCountMismatch), up == &up2 ? 1u : 0u);
    if (up == &up3) {
      EXPECT_EQ(a.toolpath.upper[1].end, Vec2(11, 11));
    }
  }
}

// ---- outputs -------------------------------------------------------------------------------

TEST(taper_outputs_test, points4_keeps_both_planes_in_step) {
  auto r = run("M101 P30\nG92 X10 Y0 U10 V0\nG3 X-10 Y0 I-10 J0 G1 U-10 V0\nM2\n");
  PointRequest req;
  req.sampling = kerf::geometry::Sampling::step(1.0);
  Diagnostics d;
  const auto out = emitPoints4(r->path(), r->source.get(), bp95dProfile(), req, false, d);
  ASSERT_TRUE(out.has_value());
  std::istringstream lines(out->text);
  double x, y, u, v;
  std::size_t n = 0;
  while (lines >> x >> y >> u >> v) {
    // The upper point is the lower one's projection on the chord: the same t on both sides.
    EXPECT_NEAR(v, 0.0, 1e-3);
    const double t = std::acos(std::clamp(x / 10.0, -1.0, 1.0)) / kerf::geometry::kPi;
    EXPECT_NEAR(u, 10.0 - 20.0 * t, 2e-3);
    ++n;
  }
  EXPECT_EQ(n, out->points);
  EXPECT_GT(n, 30u);
}

TEST(taper_outputs_test, points4_counts_against_the_capacity_before_it_samples) {
  // A half circle of radius 7 m at step 0.1 mm is ceil(pi 7000 / 0.1) = 219,912 steps and the start:
  // 219,913 point pairs, refused for a controller of
  // 500 with the count computed in closed form (it used to sample all of them first).
  auto r = run("M101 P30\nG92 X0 Y0 U0 V0\nG2 X14000 Y0 I7000 J0 G2 U14000 V0 I7000 J0\nM2\n");
  PointRequest req;
  req.sampling = kerf::geometry::Sampling::step(0.1);
  req.maxPoints = 500;
  Diagnostics d;
  EXPECT_FALSE(emitPoints4(r->path(), r->source.get(), bp95dProfile(), req, false, d).has_value());
  ASSERT_FALSE(d.all().empty());
  EXPECT_EQ(d.all().back().message, "219913 point pairs at this step, more than the 500 the controller holds");
  // Within the capacity, the rows written are exactly the rows counted.
  req.maxPoints = 300000;
  Diagnostics ok;
  const auto out = emitPoints4(r->path(), r->source.get(), bp95dProfile(), req, false, ok);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->points, 219913u);
}

TEST(taper_outputs_test, a_plane_between_the_contours_is_their_section) {
  auto r = run("M101 P20\nG92 X0 Y0 U0 V0\nG1 X10 Y0 G1 U10 V4\nM2\n");
  Diagnostics d;
  const auto flat = toolpathAtPlane(r->path(), PlaneChoice{PlaneChoice::Kind::Height, 5.0}, 1e-3, nullptr, d);
  ASSERT_TRUE(flat.has_value());
  EXPECT_NEAR(flat->moves[0].lower.end.y(), 1.0, 1e-12);
  EXPECT_TRUE(errorCodes(d).empty());
  EXPECT_FALSE(toolpathAtPlane(r->path(), PlaneChoice{PlaneChoice::Kind::Height, 25.0}, 1e-3, nullptr, d));
}

// ---- metamorphic: rigid motions, mirrors (G2 <-> G3) and reversal keep the verdicts ----------

Toolpath transformed(const Toolpath& tp, const kerf::test::Motion2& m) {
  Toolpath out = tp;
  for (auto& mv : out.moves) mv.lower = m.apply(mv.lower);
  for (auto& s : out.upper) s = m.apply(s);
  out.start = m.apply(tp.start);
  return out;
}

Toolpath reversedPath(const Toolpath& tp) {
  Toolpath out = tp;
  std::reverse(out.moves.begin(), out.moves.end());
  std::reverse(out.upper.begin(), out.upper.end());
  for (auto& mv : out.moves) mv.lower = mv.lower.reversed();
  for (auto& s : out.upper) s = s.reversed();
  if (!out.moves.empty()) out.start = out.moves.front().lower.start;
  return out;
}

std::set<Code> verdict(const Toolpath& tp) {
  Diagnostics d(1000);
  checkToolpath(tp, nullptr, {}, d);
  return errorCodes(d);
}

TEST(taper_metamorphic_test, samples_keep_their_verdicts) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const char* dir : {KERF_SAMPLES_DIR, KERF_SAMPLES_DIR "/bad"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".nc") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::size_t taperFiles = 0;
  for (const fs::path& f : files) {
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    auto r = run(text.str());
    if (!r->path().isTaper() || !r->path().heights.known) continue;
    ++taperFiles;
    const std::set<Code> base = verdict(r->path());
    for (const auto& m : kerf::test::someMotions())
      EXPECT_EQ(verdict(transformed(r->path(), m)), base) << f << " moved by angle " << m.angle;
    EXPECT_EQ(verdict(reversedPath(r->path())), base) << f << " reversed";
  }
  EXPECT_GE(taperFiles, 10u);
}

}  // namespace

namespace {

TEST(taper_test, linux_cnc_moves_uv_in_a_straight_line_during_an_arc) {
  // LinuxCNC moves the extra axes linearly during an arc (as Z in a helix): the upper side of the
  // arc block is a line, and needs no centre of its own.
  const std::string text =
      "(AXIS,XY_Z_POS,0)\n(AXIS,UV_Z_POS,20)\nG0 X35 Y60 U35 V60\nG2 R25 X60 Y35 U60 V35 F200\nM30\n";
  auto r = run(text);
  EXPECT_EQ(r->path().dialect, Dialect::XyuvLinuxCnc);
  EXPECT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  ASSERT_EQ(r->path().moves.size(), 2u);
  EXPECT_TRUE(r->path().moves[1].lower.isArc());
  EXPECT_FALSE(r->path().upper[1].isArc());
  EXPECT_NEAR((r->path().upper[1].end - Vec2(60, 35)).norm(), 0.0, 1e-12);
  // A centre of its own on the upper side belongs to another dialect.
  InterpreterOptions io;
  io.dialect = Dialect::XyuvLinuxCnc;
  auto own = run("(AXIS,UV_Z_POS,20)\nG0 X0 Y0 U0 V0\nG2 X10 Y0 I5 J0 U10 V0 I5 J0\nM30\n", io);
  EXPECT_TRUE(own->hasCode(Code::WordNotInDialect));
  // Left to detection, the words point both ways: it asks.
  EXPECT_TRUE(
      run("(AXIS,UV_Z_POS,20)\nG0 X0 Y0 U0 V0\nG2 X10 Y0 I5 J0 U10 V0 I5 J0\nM30\n")->hasCode(Code::DialectAmbiguous));
}

TEST(taper_test, xyuv_abs_upper_side_without_its_own_centre_is_a_straight_line) {
  // cnc3 takes a missing upper centre as the start point and draws that arc as a line; LinuxCNC
  // moves U V linearly. Both say: U V without a centre of their own move straight.
  auto r = run("M101 P10\nG92 X0 Y0 U0 V0\nG2 X10. Y0 I5. J0 U10. V0\nM2\n");
  EXPECT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  ASSERT_EQ(r->path().upper.size(), 1u);
  EXPECT_FALSE(r->path().upper[0].isArc());
  // With its own motion word it must have its own centre (tests/bad/upper_arc_without_centre.nc).
  EXPECT_TRUE(run("M101 P10\nG92 X0 Y0 U0 V0\nG2 X10. Y0 I5. J0 G2 U10. V0\nM2\n")->hasCode(Code::ArcWithoutCentre));
}

}  // namespace

namespace {

TEST(taper_test, ncvc_heights_in_the_set_position_of_an_xyuv_rel_program) {
  // G92 X0 Y0 U0 V0 I20 J0: U V the starting deviation, I J NCVC's thickness and program plane.
  // It is what makes the program xyuv-rel; it must not then be refused for its I J.
  auto r = run("G92 X0 Y0 U0 V0 I20. J0\nG01 X10. Y0 U0.5 V0\nX10. Y10. U0.5 V0.5\nX0 Y0 U0 V0\nM02\n");
  EXPECT_EQ(r->path().dialect, Dialect::XyuvRel);
  EXPECT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  ASSERT_TRUE(r->path().heights.known);
  EXPECT_NEAR(r->path().heights.planes.height(), 20.0, 1e-12);
}

}  // namespace

namespace {

// The sections are counted before they are made: past the budget, the twisted patches get their
// share of it and a note says so (found by the fuzzer: huge twisted arcs asked for 369,161 pieces a
// section, 1.7 s for a 4 KB program).
TEST(taper_test, sections_past_the_budget_are_coarsened_with_a_note) {
  const std::string text =
      "M101 P10\nG92 X0 Y0 U0 V0\nG1 X10 Y0 G3 U10 V0 R6\nG1 X10 Y10 G1 U10 V10\nG1 X0 Y10 G1 U0 V10\n"
      "G1 X0 Y0 G1 U0 V0\nM2\n";
  const auto fine = check(text);
  EXPECT_TRUE(errorCodes(fine->diags).empty());
  EXPECT_FALSE(fine->hasCode(Code::SectionsCoarsened));
  CheckOptions co;
  co.sectionBudget = 10;
  const auto coarse = check(text, co);
  EXPECT_TRUE(errorCodes(coarse->diags).empty());
  ASSERT_TRUE(coarse->hasCode(Code::SectionsCoarsened));
  std::size_t notes = 0;
  for (const auto& d : coarse->diags.all())
    if (d.code == Code::SectionsCoarsened) {
      ++notes;
      EXPECT_EQ(d.severity, Severity::Note);
      EXPECT_NE(d.message.find("budget of 10"), std::string::npos) << d.message;
    }
  EXPECT_EQ(notes, 1u) << "one note, not one per section";
}

}  // namespace
