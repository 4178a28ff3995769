#include "converter_support.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/report/report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace kerf::converter;
using kerf::geometry::Vec2;
using kerf::test::run;

namespace {

constexpr double kEps = 1e-9;

TEST(interpreter_test, absolute_and_incremental_moves) {
  auto r = run("G90 G01 X10. Y0\nG91 X5. Y5.\nG90 X0 Y0\nM02\n");
  ASSERT_FALSE(r->diags.hasErrors());
  const auto& m = r->path().moves;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[1].lower.end, Vec2(15, 5));
  EXPECT_EQ(m[2].lower.end, Vec2(0, 0));
  EXPECT_TRUE(r->path().endedProperly);
}

TEST(interpreter_test, modal_motion_carries_over) {
  auto r = run("G01 X1.\nY1.\nX0\nM30\n");
  ASSERT_EQ(r->path().moves.size(), 3u);
  for (const auto& m : r->path().moves) EXPECT_EQ(m.kind, MoveKind::Line);
}

TEST(interpreter_test, inch_units_are_converted_to_mm) {
  auto r = run("G20 G01 X1. Y0.5\nM02\n");
  ASSERT_EQ(r->path().moves.size(), 1u);
  EXPECT_NEAR(r->path().moves[0].lower.end.x(), 25.4, kEps);
  EXPECT_NEAR(r->path().moves[0].lower.end.y(), 12.7, kEps);
  auto r70 = run("G70 G01 X1.\nG71 X1.\nM02\n");
  EXPECT_NEAR(r70->path().moves[1].lower.end.x(), 1.0, kEps);
}

TEST(interpreter_test, integer_micrometres) {
  InterpreterOptions o;
  o.integerUnit = IntegerUnit::Micrometre;
  auto r = run("G92 X115000 Y-10000\nG91 G01 X-9900 Y0\nX1.5\nM02\n", o);
  ASSERT_FALSE(r->diags.hasErrors());
  EXPECT_NEAR(r->path().start.x(), 115.0, kEps);
  EXPECT_NEAR(r->path().moves[0].lower.end.x(), 105.1, kEps);
  // A number with a decimal point stays in mm.
  EXPECT_NEAR(r->path().moves[1].lower.end.x(), 106.6, kEps);
  EXPECT_FALSE(r->hasCode(Code::IntegerUnitSuspect));
  auto warned = run("G92 X115000 Y-10000\nG91 G01 X-9900 Y0\nM02\n");
  EXPECT_TRUE(warned->hasCode(Code::IntegerUnitSuspect));
}

TEST(interpreter_test, arc_centre_modes) {
  // The same quarter circle about the origin, from (10, 0) to (0, 10), with I J written three ways.
  struct Case {
    ArcCentreMode mode;
    const char* ij;
    CentreForm form;
  };
  for (const Case c : {Case{ArcCentreMode::Incremental, "I-10. J0", CentreForm::Incremental},
                       Case{ArcCentreMode::Reversed, "I10. J0", CentreForm::Reversed},
                       Case{ArcCentreMode::Absolute, "I0 J0", CentreForm::Absolute}}) {
    SCOPED_TRACE(c.ij);
    InterpreterOptions o;
    o.arcCentre = c.mode;
    auto r = run(std::string("G92 X10. Y0\nG03 X0 Y10. ") + c.ij + "\nM02\n", o);
    ASSERT_FALSE(r->diags.hasErrors());
    EXPECT_NEAR(r->path().moves[0].lower.centre.norm(), 0, kEps);
    EXPECT_EQ(r->path().moves[0].centreForm, c.form);
  }
  // The wrong convention is caught: absolute centre words read as incremental put the centre on
  // the start point.
  auto wrong = run("G92 X10. Y0\nG03 X0 Y10. I0 J0\nM02\n");
  EXPECT_TRUE(wrong->hasCode(Code::ZeroRadius));
  // Reversed words read as incremental: end point 14 mm off the circle, with the hint.
  auto reversed = run("G92 X10. Y0\nG03 X0 Y10. I10. J0\nM02\n");
  ASSERT_TRUE(reversed->hasCode(Code::ArcEndOffCircle));
  EXPECT_NE(reversed->diags.all()[0].help.find("--arc-centre"), std::string::npos);
}

TEST(interpreter_test, full_circle_from_centre_words) {
  auto r = run("G92 X5. Y0\nG02 I-5. J0\nM02\n");
  ASSERT_FALSE(r->diags.hasErrors());
  ASSERT_EQ(r->path().moves.size(), 1u);
  EXPECT_NEAR(std::abs(r->path().moves[0].lower.sweep), 2 * M_PI, kEps);
}

TEST(interpreter_test, g92_mid_program_shifts_the_frame_not_the_wire) {
  auto r = run("G92 X0 Y0\nG01 X10. Y0\nG92 X0 Y0\nG01 X5. Y0\nM02\n");
  ASSERT_EQ(r->path().moves.size(), 2u);
  // The second move starts where the wire is (10, 0) and goes 5 mm further.
  EXPECT_EQ(r->path().moves[1].lower.start, Vec2(10, 0));
  EXPECT_EQ(r->path().moves[1].lower.end, Vec2(15, 0));
}

TEST(interpreter_test, dwell_x_is_time_not_a_coordinate) {
  auto r = run("G01 X1.\nG04 X2.5\nG01 Y1.\nM02\n");
  ASSERT_FALSE(r->diags.hasErrors());
  ASSERT_EQ(r->path().moves.size(), 2u);
  EXPECT_EQ(r->path().moves[1].lower.start, Vec2(1, 0));
}

TEST(interpreter_test, subprogram_with_repeats_in_incremental_mode) {
  auto r = run("G91 G01 X1.\nM98 P100 L3\nM02\nO100\nG01 X2.\nM99\n");
  ASSERT_FALSE(r->diags.hasErrors());
  ASSERT_EQ(r->path().moves.size(), 4u);
  EXPECT_EQ(r->path().moves.back().lower.end, Vec2(7, 0));
  EXPECT_EQ(r->path().moves.back().callDepth, 1);
  EXPECT_EQ(r->path().moves.back().line, 5u);  // the move names the subprogram's line
}

TEST(interpreter_test, sodick_style_n_label_after_m02) {
  auto r = run("H001 = +000000.1300;\nG90 G01 X0 Y0;\nM98 P0001;\nM02;\nN0001 G41 H001 G01 X1.;\nM99;\n");
  ASSERT_FALSE(r->diags.hasErrors());
  ASSERT_EQ(r->path().moves.size(), 2u);
  EXPECT_EQ(r->path().moves[1].wireOffset, WireOffset::Left);
  EXPECT_TRUE(r->path().offsetRole.empty()) << "a start-up move alone compensates nothing";
}

TEST(interpreter_test, g41_with_an_h_register_is_applied_with_arcs_at_convex_corners) {
  // A 10 x 10 square cut clockwise from a lead-in, the wire 0.13 to the left (outside).
  auto r =
      run("H001 = +000000.1300;\nG90 G92 X-5 Y0;\nG41 H001 G01 X0 Y0;\nG01 X0 Y10;\nG01 X10 Y10;\nG01 X10 Y0;\n"
          "G01 X0 Y0;\nG40 G01 X-5 Y0;\nM02;\n");
  ASSERT_FALSE(r->diags.hasErrors());
  const auto& t = r->path();
  ASSERT_EQ(t.offsetRole.size(), t.moves.size());
  // start-up, 4 sides with 3 corner arcs between them, cancel
  ASSERT_EQ(t.moves.size(), 9u);
  EXPECT_EQ(t.offsetRole.front(), kerf::converter::OffsetRole::StartUp);
  EXPECT_EQ(t.offsetRole.back(), kerf::converter::OffsetRole::Cancel);
  int corners = 0;
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    if (t.offsetRole[i] != kerf::converter::OffsetRole::Corner) continue;
    ++corners;
    EXPECT_NEAR(t.moves[i].lower.radius(), 0.13, 1e-12);
    EXPECT_LT(t.moves[i].lower.sweep, 0) << "a left offset rolls clockwise round a convex corner";
  }
  EXPECT_EQ(corners, 3);
  EXPECT_NEAR(t.moves[1].lower.start.x(), -0.13, 1e-12);   // the first side, moved left of travel
  EXPECT_NEAR(t.moves.back().lower.end.x(), -5.0, 1e-12);  // the cancel returns to the programmed point
  EXPECT_TRUE(r->hasCode(Code::WireOffsetApplied));        // the note that it was applied
  EXPECT_FALSE(r->hasCode(Code::WireOffsetNotApplied));
}

TEST(interpreter_test, explain_derives_an_offset_arc_from_its_programmed_words) {
  // G41 left of a line, then an R arc: the corner arc has no words (its centre is the corner), the
  // offset arc's centre follows from R on the programmed chord (10 mm), not the offset one.
  auto r =
      run("H001 = +000000.2000;\nG90 G92 X-5 Y0;\nG41 H001 G01 X0 Y0;\nG01 X10 Y0;\nG03 X20 Y0 R5;\n"
          "G01 X20 Y-10;\nG01 X0 Y-10;\nG01 X0 Y0;\nG40 G01 X-5 Y0;\nM02;\n");
  ASSERT_FALSE(r->diags.hasErrors());
  const std::string text = kerf::converter::explainText(*r->source, r->path(), kerf::geometry::Sampling::step(0.1));
  EXPECT_NE(text.find("centre (10.000, 0.000): the programmed corner; radius = the wire offset 0.200 mm"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("centre (15.000, 0.000) from R 5.000: half the chord of the programmed arc is 5.000 mm"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("the wire path keeps that centre, inside the programmed arc by the offset"), std::string::npos);
}

TEST(interpreter_test, recursion_is_stopped) {
  auto r = run("O1\nG91 G01 X1.\nM98 P1\nM99\n");
  EXPECT_TRUE(r->hasCode(Code::CallTooDeep));
  EXPECT_LE(r->path().moves.size(), 17u);
}

TEST(interpreter_test, execution_limits_bound_time_and_memory) {
  InterpreterOptions o;
  o.maxMoves = 1000;
  auto r = run("G91 G01\nM98 P1 L9999\nM02\nO1 M98 P2 L9999\nM99\nO2 X1.\nM99\n", o);
  EXPECT_TRUE(r->hasCode(Code::ExecutionLimit));
  EXPECT_LE(r->path().moves.size(), 1001u);
  InterpreterOptions b;
  b.maxExecutedBlocks = 5000;
  auto r2 = run("G91\nM98 P1 L9999\nM02\nO1 M98 P2 L9999\nM99\nO2 G04 P0\nM99\n", b);
  EXPECT_TRUE(r2->hasCode(Code::ExecutionLimit));
}

TEST(interpreter_test, block_delete_skips_when_enabled) {
  auto on = run("G01 X1.\n/G01 Y5.\nM02\n");
  EXPECT_EQ(on->path().moves.size(), 1u);
  InterpreterOptions o;
  o.blockDelete = false;
  auto off = run("G01 X1.\n/G01 Y5.\nM02\n", o);
  EXPECT_EQ(off->path().moves.size(), 2u);
}

TEST(interpreter_test, rapid_moves_are_not_cut) {
  auto r = run("G00 X5.\nG01 X6.\nM02\n");
  ASSERT_EQ(r->path().moves.size(), 2u);
  EXPECT_FALSE(r->path().moves[0].isCut());
  EXPECT_TRUE(r->path().moves[1].isCut());
}

// The summary's box is the union of the cut moves' own boxes, bit for bit: arcs whose circle lies
// inside the box of the ends skip the test of their extremes, arcs that bulge past it do not.
TEST(interpreter_test, summary_bounds_are_the_union_of_the_moves_boxes) {
  // End points on a 30 mm square, and four half circles that each bulge 5 mm past one of its
  // sides alone (clockwise: left, top, right, bottom), then small arcs well inside it.
  std::string program = "G90 G21 G92 X0 Y0\nG01 X30. Y0\nX30. Y30.\nX0 Y30.\nX0 Y10.\n";
  program += "G02 X0 Y20. R5.\nG01 X10. Y30.\nG02 X20. Y30. R5.\nG01 X30. Y20.\nG02 X30. Y10. R5.\n";
  program += "G01 X20. Y0\nG02 X10. Y0 R5.\nG01 X15. Y15.\n";
  for (int k = 0; k < 40; ++k)
    program += std::string(k % 2 ? "G02" : "G03") + " X" + std::to_string(15.1 + 0.1 * k) + " Y" +
               std::to_string(15.0 + 0.05 * (k % 3)) + " R0.3\n";
  program += "M02\n";
  auto r = run(program);
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  kerf::geometry::Box expected, ends;
  std::size_t arcs = 0;
  for (const Move& m : r->path().moves)
    if (m.isCut()) {
      expected.add(m.lower.bounds());
      ends.add(m.lower.start);
      ends.add(m.lower.end);
      arcs += m.lower.isArc();
    }
  ASSERT_EQ(arcs, 44u);
  const Summary s = summarize(r->path(), kerf::geometry::Sampling::step(0.1));
  EXPECT_EQ(s.bounds.min.x(), expected.min.x());
  EXPECT_EQ(s.bounds.min.y(), expected.min.y());
  EXPECT_EQ(s.bounds.max.x(), expected.max.x());
  EXPECT_EQ(s.bounds.max.y(), expected.max.y());
  // Each side was moved by its half circle's extreme, not by an end point.
  EXPECT_DOUBLE_EQ(s.bounds.min.x(), ends.min.x() - 5.0);
  EXPECT_DOUBLE_EQ(s.bounds.min.y(), ends.min.y() - 5.0);
  EXPECT_DOUBLE_EQ(s.bounds.max.x(), ends.max.x() + 5.0);
  EXPECT_DOUBLE_EQ(s.bounds.max.y(), ends.max.y() + 5.0);
}

TEST(interpreter_test, every_move_keeps_its_block_span) {
  auto r = run("G01 X1.\n\n  G02 X2. Y1. R1.\nM02\n");
  ASSERT_EQ(r->path().moves.size(), 2u);
  const auto& m = r->path().moves[1];
  EXPECT_EQ(m.line, 3u);
  EXPECT_EQ(r->source->text().substr(m.span.offset, m.span.length), "G02 X2. Y1. R1.");
}

TEST(interpreter_test, missing_program_end_is_a_warning) {
  auto r = run("G01 X1.\n");
  EXPECT_TRUE(r->hasCode(Code::MissingProgramEnd));
  EXPECT_FALSE(r->diags.hasErrors());
}

TEST(interpreter_test, unknown_g_code_names_the_profile_that_knows_it) {
  // G60 is no standard code: the generic profile refuses it and says which profile knows it,
  // instead of guessing at typos ("G00 or G20 ...").
  InterpreterOptions io;
  io.machine = findBuiltinMachine("generic");
  auto r = run("G60\nG01 X1.\nM02\n", io);
  ASSERT_TRUE(r->hasCode(Code::UnknownGCode));
  EXPECT_NE(r->diags.all()[0].help.find("--machine robofil"), std::string::npos) << r->diags.all()[0].help;
  // Under the robofil profile it is a note, once.
  io.machine = findBuiltinMachine("robofil");
  auto known = run("G60\nG01 X1.\nG60\nM02\n", io);
  EXPECT_FALSE(known->diags.hasErrors());
  EXPECT_EQ(std::count_if(known->diags.all().begin(), known->diags.all().end(),
                          [](const Diagnostic& d) { return d.code == Code::MachineCode; }),
            1);
  // A code no profile knows gets no help at all.
  io.machine = findBuiltinMachine("generic");
  auto unknown = run("G05 X1.\nM02\n", io);
  ASSERT_TRUE(unknown->hasCode(Code::UnknownGCode));
  EXPECT_TRUE(unknown->diags.all()[0].help.empty());
}

TEST(checks_test, retrace_is_a_note_and_crossing_an_error) {
  auto clean = run("G92 X-5. Y0\nG01 X0 Y0\nX10.\nY10.\nX0\nY0\nX-5.\nM02\n", {}, true);
  EXPECT_FALSE(clean->diags.hasErrors());
  EXPECT_TRUE(clean->hasCode(Code::PathRetraces));
  auto crossing = run("G92 X0 Y0\nG01 X10. Y10.\nX10. Y0\nX0 Y10.\nX0 Y0\nM02\n", {}, true);
  EXPECT_TRUE(crossing->hasCode(Code::PathCrossesItself));
  ASSERT_TRUE(crossing->diags.hasErrors());
  for (const auto& d : crossing->diags.all())
    if (d.code == Code::PathCrossesItself) {
      ASSERT_TRUE(d.point.has_value());
      EXPECT_NEAR(d.point->x(), 5.0, 1e-9);
      ASSERT_TRUE(d.move.has_value());
    }
}

TEST(checks_test, open_path_is_a_warning) {
  auto r = run("G01 X10.\nY10.\nM02\n", {}, true);
  EXPECT_TRUE(r->hasCode(Code::PathOpen));
  EXPECT_FALSE(r->diags.hasErrors());
}

}  // namespace

namespace {

TEST(checks_test, a_touch_that_closes_the_contour_is_a_note_however_the_blocks_are_split) {
  // IGK1-style: the last block closes the contour at the lead-in's end and runs on down the
  // lead-in. Split at that point it meets itself only at shared vertices: the same verdict.
  const std::string whole = "G92 X0 Y0\nG01 Y10.\nX-20.\nY20.\nX0\nY0\nM02\n";
  const std::string split = "G92 X0 Y0\nG01 Y10.\nX-20.\nY20.\nX0\nY10.\nY0\nM02\n";
  auto a = run(whole, {}, true), b = run(split, {}, true);
  EXPECT_FALSE(a->diags.hasErrors()) << kerf::test::dump(a->diags);
  EXPECT_FALSE(b->diags.hasErrors()) << kerf::test::dump(b->diags);
  EXPECT_TRUE(a->hasCode(Code::LoopClosesInsideMove));
  // A loop closing on the lead-in and ending there (the cut ends at the closure).
  auto c = run("G92 X0 Y0\nG01 X10. Y0\nX10. Y5.\nX5.\nY0\nM02\n", {}, true);
  EXPECT_FALSE(c->diags.hasErrors()) << kerf::test::dump(c->diags);
  EXPECT_TRUE(c->hasCode(Code::LoopClosesInsideMove));
  // A pinch: the path touches itself and goes on cutting something else. A true touch: an error.
  auto pinch = run("G92 X0 Y0\nG01 X10. Y0\nX10. Y10.\nX5. Y0\nX0 Y10.\nX0 Y0\nM02\n", {}, true);
  EXPECT_TRUE(pinch->hasCode(Code::PathTouchesItself));
  EXPECT_FALSE(pinch->hasCode(Code::LoopClosesInsideMove));
}

TEST(interpreter_test, a_bare_g92_makes_the_current_position_the_origin_on_robofil) {
  InterpreterOptions io;
  io.machine = findBuiltinMachine("robofil");
  auto r = run("G01 X5. Y2.\nG92\nG01 X1. Y0\nM02\n", io);
  EXPECT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  ASSERT_EQ(r->path().moves.size(), 2u);
  // X1 Y0 is now 1 mm right of (5, 2).
  EXPECT_NEAR((r->path().moves[1].lower.end - kerf::geometry::Vec2(6, 2)).norm(), 0.0, 1e-12);
}

TEST(interpreter_test, the_polar_section_is_one_error_and_what_follows_is_said_once) {
  // The section's blocks are not read (one error); where it left the wire is unknown, so the cut
  // after it cannot be checked (one more error, for every such move together).
  auto r = run("G92 X0 Y0\nG01 X10.\nG112\nG1 X5. C1.\nG3 X4. C2. R1.\nG113\nG01 X20.\nX30.\nM30\n");
  std::vector<Code> errors;
  for (const auto& d : r->diags.all())
    if (d.severity == Severity::Error) errors.push_back(d.code);
  EXPECT_EQ(errors, (std::vector<Code>{Code::PolarNotSupported, Code::PositionUnknown})) << kerf::test::dump(r->diags);
  EXPECT_EQ(r->path().moves.size(), 1u);
  // A polar section that ends the program leaves nothing to say after it.
  auto end = run("G92 X0 Y0\nG01 X10.\nG112\nG1 X5. C1.\nG113\nM30\n");
  EXPECT_FALSE(end->hasCode(Code::PositionUnknown)) << kerf::test::dump(end->diags);
}

}  // namespace

namespace {

// The checks read the cut path in place when no rapid lies between cuts, and copy it only when one
// does: either way the view holds the cut moves' lower segments, in order.
TEST(cut_view_test, reads_contiguous_cuts_in_place_and_copies_otherwise) {
  auto r = run("G00 X1. Y0\nG01 X2.\nG03 X2. Y2. I0 J1.\nG01 X1. Y0\nG00 X0 Y0\nM02\n");
  ASSERT_FALSE(r->diags.hasErrors()) << kerf::test::dump(r->diags);
  const auto& moves = r->path().moves;
  ASSERT_EQ(moves.size(), 5u);
  const CutView in = cutView(r->path());
  EXPECT_TRUE(in.copy.empty());
  ASSERT_EQ(in.segments.size(), 3u);
  ASSERT_EQ(in.moveIndex.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(in.moveIndex[k], k + 1);
    EXPECT_EQ(&in.segments[k], &moves[k + 1].lower);  // the move's own segment, not a copy
  }
  std::size_t visited = 0;
  for (const kerf::geometry::Segment& s : in.segments) EXPECT_EQ(&s, &moves[++visited].lower);
  EXPECT_EQ(visited, 3u);
  EXPECT_EQ(in.segments.back().kind, kerf::geometry::SegmentKind::Line);

  auto gap = run("G01 X1. Y0\nG00 X5.\nG01 X6.\nX6. Y1.\nM02\n");
  const CutView copied = cutView(gap->path());
  ASSERT_EQ(copied.segments.size(), 3u);
  EXPECT_FALSE(copied.copy.empty());
  EXPECT_EQ(copied.table, (std::vector<std::uint32_t>{0, 2, 3}));
  ASSERT_EQ(copied.moveIndex.size(), 3u);
  EXPECT_EQ(copied.moveIndex[1], 2u);
  EXPECT_EQ(copied.moveIndex.back(), 3u);
  EXPECT_TRUE(in.table.empty());  // contiguous: first + k, nothing stored
  EXPECT_EQ(copied.segments[1].start, Vec2(5, 0));
  EXPECT_EQ(copied.segments[2].end, Vec2(6, 1));

  // Moving the view keeps it valid (it may point into its own copy).
  CutView moved = cutView(gap->path());
  const CutView again = std::move(moved);
  EXPECT_EQ(again.segments[2].end, Vec2(6, 1));
  EXPECT_EQ(again.moveIndex[2], 3u);

  auto none = run("G00 X1. Y0\nM02\n");
  EXPECT_TRUE(cutView(none->path()).segments.empty());
}

}  // namespace
