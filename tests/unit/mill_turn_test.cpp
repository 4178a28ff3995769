// Mill-turn face programs through the interpreter's phases (interpret/mill_turn.cpp,
// docs/polar.md): phase 1's words, and phase 4's face point outside and inside G12.1, with the
// expected points worked out here by hand.
#include "kerf/converter/interpret/mill_turn.h"
#include "converter_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace kerf::converter;
using kerf::geometry::Vec2;
using kerf::test::run;

namespace {

InterpreterOptions face(bool frameTable = false) {
  InterpreterOptions o;
  o.millTurn = MillTurnOptions{};
  o.millTurn->polarFrameTable = frameTable;
  return o;
}

std::size_t count(const kerf::test::Run& r, Code c) {
  std::size_t n = 0;
  for (const auto& d : r.diags.all()) n += d.code == c;
  return n;
}

TEST(mill_turn_test, x_is_a_diameter_and_c_the_table_angle) {
  auto r = run("G0 X20. C0\nC90.\nX-20.\nM30\n", face());
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  const auto& m = r->path().moves;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_NEAR((m[0].lower.end - Vec2(10, 0)).norm(), 0.0, 1e-12);   // diameter 20 at C 0
  EXPECT_NEAR((m[1].lower.end - Vec2(0, 10)).norm(), 0.0, 1e-12);   // the table turned 90 degrees
  EXPECT_EQ(m[1].kind, MoveKind::Rapid);                            // a rapid: drawn as the chord
  EXPECT_NEAR((m[2].lower.end - Vec2(0, -10)).norm(), 0.0, 1e-12);  // a negative diameter: across
}

TEST(mill_turn_test, an_x_c_cut_is_drawn_as_the_machines_spiral) {
  auto r = run("G0 X20. C0\nG1 X10. C90. F100.\nM30\n", face());
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  const auto& m = r->path().moves;
  ASSERT_GT(m.size(), 2u);  // the rapid and the spiral's pieces
  EXPECT_NEAR((m.back().lower.end - Vec2(0, 5)).norm(), 0.0, 1e-12);
  // Halfway in C (45 degrees) the machine is at radius 7.5: some piece passes within 0.1 um.
  const Vec2 half = 7.5 * Vec2(std::cos(M_PI / 4), std::sin(M_PI / 4));
  double nearest = 1e300;
  for (std::size_t k = 1; k < m.size(); ++k) nearest = std::min(nearest, m[k].lower.distanceTo(half));
  EXPECT_LT(nearest, 1e-4);
  EXPECT_EQ(count(*r, Code::PolarAxisValue), 1u);  // the spirals are said once
}

TEST(mill_turn_test, polar_interpolation_turns_its_frame_with_the_table_unless_told_otherwise) {
  const std::string text = "G0 X20. C90.\nG12.1\nG1 X5. C0 F100.\nG13.1\nM30\n";
  auto tool = run(text, face());
  ASSERT_FALSE(tool->diags.hasErrors()) << kerf::test::dump(tool->diags);
  // At G12.1 the tool is at (0, 10), the frame's x axis through it: X5 C0 is (0, 5).
  EXPECT_NEAR((tool->path().moves.back().lower.end - Vec2(0, 5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(count(*tool, Code::PolarAxisValue), 1u);  // the turned frame is said
  auto table = run(text, face(true));
  EXPECT_NEAR((table->path().moves.back().lower.end - Vec2(5, 0)).norm(), 0.0, 1e-12);
}

TEST(mill_turn_test, i_j_inside_polar_interpolation_are_in_the_turned_frame) {
  // From (10, 0) in the frame turned 90 degrees (the tool at (0, 10)) half a circle about the
  // centre: I-10 is (0, -10) on the face, so the centre is the origin.
  auto r = run("G0 X20. C90.\nG12.1\nG3 X-10. C0 I-10. J0 F100.\nG13.1\nM30\n", face());
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  const auto& arc = r->path().moves.back();
  ASSERT_EQ(arc.kind, MoveKind::Arc);
  EXPECT_NEAR(arc.lower.centre.norm(), 0.0, 1e-9);
  EXPECT_NEAR((arc.lower.end - Vec2(0, -10)).norm(), 0.0, 1e-12);
}

TEST(mill_turn_test, words_that_do_not_move_the_face_point_are_said_once_and_planes_pass) {
  auto r = run("T0101\nG18 S1000 M03\nG0 X10. C0 Z5.\nS2000 M03\nT0101\nG41 G1 X8. F50.\nG40 G0 X20.\nM30\n", face());
  EXPECT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  EXPECT_EQ(count(*r, Code::MachineCode), 4u) << kerf::test::dump(r->diags);      // T101, S1000, M3, S2000
  EXPECT_EQ(count(*r, Code::CodeNotModelled), 1u) << kerf::test::dump(r->diags);  // G41 is not applied
  EXPECT_EQ(count(*r, Code::PlaneNotSupported), 0u);
  EXPECT_EQ(count(*r, Code::WordIgnored), 0u);  // Z is the depth
  ASSERT_EQ(r->path().moves.size(), 3u);
  EXPECT_NEAR((r->path().moves[1].lower.end - Vec2(4, 0)).norm(), 0.0, 1e-12);
}

TEST(mill_turn_test, a_cut_that_turns_the_table_the_long_way_is_an_error_at_its_c) {
  auto r = run("G0 X20. C10.\nG1 C-200. F100.\nM30\n", face());
  ASSERT_EQ(count(*r, Code::RotaryJump), 1u) << kerf::test::dump(r->diags);
  EXPECT_TRUE(r->diags.hasErrors());
}

}  // namespace
