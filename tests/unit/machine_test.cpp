// Machine profiles: the built-ins, the text format, detection from a program's evidence, and what
// a profile changes in the reading (through the pipeline every command takes).
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/pipeline.h"
#include "kerf/converter/report/report.h"

#include "converter_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace kerf::converter;

Pipeline read(const std::string& text, PipelineOptions options = {}) { return runPipeline({"p.nc", text}, options); }

bool has(const Pipeline& p, Code c) {
  return std::any_of(p.diags.all().begin(), p.diags.all().end(), [c](const Diagnostic& d) { return d.code == c; });
}

const Diagnostic& first(const Pipeline& p, Code c) {
  static const Diagnostic none{};
  for (const Diagnostic& d : p.diags.all())
    if (d.code == c) return d;
  ADD_FAILURE() << "no " << codeName(c) << " reported";
  return none;
}

TEST(machine_test, every_built_in_profile_parses_and_is_listed_in_order) {
  const auto& all = builtinMachines();
  std::vector<std::string> names;
  for (const MachineProfile& m : all) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"generic", "robofil", "sodick", "linuxcnc", "cnc3", "ncvc", "fanuc"}));
  for (const MachineProfile& m : all) {
    EXPECT_FALSE(m.summary.empty()) << m.name;
    EXPECT_FALSE(m.sources.empty()) << m.name;
    for (const KnownCode& c : m.codes) EXPECT_FALSE(c.note.empty()) << m.name << " " << c.key;
    // What `kerf machines show` prints reads back as the same profile.
    SourceFile file(m.name + ".profile", m.text);
    Diagnostics d;
    const auto again = parseMachineProfile(file, d);
    ASSERT_TRUE(again.has_value()) << m.name;
    EXPECT_EQ(again->codes.size(), m.codes.size());
  }
}

TEST(machine_test, profile_lines_are_checked_at_their_place) {
  SourceFile file("my.profile",
                  "name = mine\narc_centre = sideways\ncode G0x2 = harmless: x\nsize = 3\ncode G60 = harmless\n");
  Diagnostics d;
  EXPECT_FALSE(parseMachineProfile(file, d).has_value());
  ASSERT_EQ(d.errorCount(), 4u);
  for (const Diagnostic& x : d.all()) EXPECT_EQ(x.code, Code::MachineProfileError);
  EXPECT_EQ(file.locate(d.all()[0].span.offset).line, 2u);
  EXPECT_EQ(file.locate(d.all()[0].span.offset).column, 14u);
  EXPECT_EQ(file.locate(d.all()[3].span.offset).line, 5u);  // a code needs its note
}

TEST(machine_test, two_valued_keys_take_either_value_and_name_both_otherwise) {
  SourceFile on("on.profile",
                "semicolon = end-of-block\nupper_axes = uz\nbare_g92 = origin\nlegacy_taper_codes = detect\n");
  SourceFile off("off.profile", "semicolon = comment\nupper_axes = uv\nbare_g92 = error\nlegacy_taper_codes = no\n");
  Diagnostics d;
  const auto a = parseMachineProfile(on, d);
  const auto b = parseMachineProfile(off, d);
  ASSERT_TRUE(a && b) << kerf::test::dump(d);
  EXPECT_TRUE(a->semicolonEndsBlock && a->upperAxesUZ && a->bareSetPositionIsOrigin && a->legacyTaperCodes);
  EXPECT_FALSE(b->semicolonEndsBlock || b->upperAxesUZ || b->bareSetPositionIsOrigin || b->legacyTaperCodes);
  SourceFile bad("bad.profile", "upper_axes = uw\n");
  EXPECT_FALSE(parseMachineProfile(bad, d).has_value());
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all()[0].help, "allowed: uv or uz");
  EXPECT_EQ(bad.locate(d.all()[0].span.offset).column, 14u);
}

TEST(machine_test, codes_are_written_any_way_and_found_one_way) {
  SourceFile file(
      "m.profile",
      "code g02.0 = harmless: a\ncode G12.1 = harmless: b\ncode qaic = harmless: c\ncode c = harmless: d\n");
  Diagnostics d;
  const auto m = parseMachineProfile(file, d);
  ASSERT_TRUE(m.has_value()) << kerf::test::dump(d);
  EXPECT_NE(m->find("G2"), nullptr);
  EXPECT_NE(m->find("G12.1"), nullptr);
  EXPECT_NE(m->find("QAIC"), nullptr);
  EXPECT_NE(m->find("C"), nullptr);
  EXPECT_EQ(m->name, "m");  // from the file's name when the file names none
}

TEST(machine_test, detected_from_the_evidence_and_said_once) {
  struct Case {
    const char* text;
    const char* machine;
  } cases[] = {
      {"% (MEM:A.ISO)\nG92X0Y0\nG60\nG01X100Y0\nM02\n", "robofil"},
      {"C000 = 012 014;\nH000 = +000000.0100 ;\nG92 X0 Y0;\nG01 X1.;\nM02;\n", "sodick"},
      {"(AXIS,XY_Z_POS,0)\n(AXIS,UV_Z_POS,10)\ng1 x1 y1 u1 v1\nm2\n", "linuxcnc"},
      {"M100 P375 Q117\nM101 P20\nG92 X0 Y0 U0 V0\nG1 X5 Y0 G1 U5 V0\nM2\n", "cnc3"},
      {"G92 X0 Y0 I20. J0\nG01 X10. Y0 U1. V0\nM02\n", "ncvc"},
      {"O0001\nG112\nG1 X1. C1.\nG113\nM30\n", "fanuc"},
      {"G92 X0 Y0\nG01 X10. Y0\nM02\n", "generic"},
  };
  for (const Case& c : cases) {
    const Pipeline p = read(c.text);
    EXPECT_EQ(p.machine.name, c.machine) << c.text;
    EXPECT_TRUE(p.machineDetected);
    const auto notes = std::count_if(p.diags.all().begin(), p.diags.all().end(),
                                     [](const Diagnostic& d) { return d.code == Code::MachineDetected; });
    EXPECT_EQ(notes, std::string(c.machine) == "generic" ? 0 : 1) << c.text;
  }
  // A single weak hint is not enough.
  EXPECT_EQ(read("G92 X0 Y0\nG99\nG01 X10.\nM02\n").machine.name, "generic");
}

TEST(machine_test, micrometres_and_absolute_centres_from_the_evidence) {
  // No decimal point anywhere and integers in the thousands: micrometres; the arcs close only
  // about absolute centres. The note names both pieces of evidence.
  const std::string text = "G92X0Y0\nG01X6500Y0\nG03X-6500Y0I0J0\nG03X6500Y0I0J0\nM02\n";
  const Pipeline p = read(text);
  EXPECT_EQ(p.toolpath.reading.integerUnit, IntegerUnit::Micrometre);
  EXPECT_EQ(p.toolpath.reading.arcCentre, ArcCentreMode::Absolute);
  EXPECT_FALSE(p.diags.hasErrors()) << kerf::test::dump(p.diags);
  const std::string& note = first(p, Code::MachineDetected).message;
  EXPECT_NE(note.find("µm integers: 12 coordinates without a decimal point, largest 6500"), std::string::npos) << note;
  EXPECT_NE(note.find("absolute centres: 2 of 2 arcs close only that way"), std::string::npos) << note;
  EXPECT_NEAR(p.toolpath.moves[1].lower.radius(), 6.5, 1e-12);
  // Explicit options win over the evidence.
  PipelineOptions o;
  o.read.integerUnit = IntegerUnit::Millimetre;
  o.read.arcCentre = ArcCentreMode::Incremental;
  const Pipeline forced = read(text, o);
  EXPECT_TRUE(has(forced, Code::ZeroRadius));
  EXPECT_NE(first(forced, Code::ZeroRadius).help.find("--arc-centre absolute"), std::string::npos);
}

// Issue 42: the I J convention is decided by arcs that close one way only. An arc that closes no
// way is no evidence against the others: it is an error of its own, at its line, under the
// convention they decide. Arcs that close either way decide nothing: the profile's default holds.
TEST(machine_test, an_arc_that_closes_no_way_does_not_decide_the_centre_convention) {
  const Pipeline p = read("G92 X0 Y0\nG01 X10. Y0\nG03 X-10. Y0 I0 J0\nG03 X10. Y0 I0 J0\nG03 X0 Y7. I0 J0\nM02\n");
  EXPECT_EQ(p.toolpath.reading.arcCentre, ArcCentreMode::Absolute) << kerf::test::dump(p.diags);
  ASSERT_TRUE(has(p, Code::ArcEndOffCircle)) << kerf::test::dump(p.diags);
  EXPECT_EQ(p.source->locate(first(p, Code::ArcEndOffCircle).span.offset).line, 5u);
  EXPECT_FALSE(has(p, Code::ZeroRadius));  // the two good arcs read as the evidence says
  // Arcs from the origin close both ways: no evidence, the default (incremental) holds.
  const Pipeline both = read("G92 X0 Y0\nG02 X0 Y0 I5. J0\nG01 X3. Y0\nG03 X0 Y7. I1. J1.\nM02\n");
  EXPECT_EQ(both.toolpath.reading.arcCentre, ArcCentreMode::Incremental) << kerf::test::dump(both.diags);
  EXPECT_TRUE(has(both, Code::ArcEndOffCircle));
}

// A long program that runs straight through gives its parse tree back as it runs (many thousand
// blocks, pages at a time). What it reads must not change: the same moves as a run that keeps the
// tree; a diagnostic that points at the motion word of the first block, 30,000 blocks later; and a
// second run under the absolute-centre convention, which must parse the program again.
TEST(machine_test, a_long_program_reads_the_same_when_its_parse_tree_goes_back_as_it_runs) {
  std::string text = "G92 X0 Y0\nG01 X1. Y0\n";
  for (int i = 0; i < 30000; ++i) text += "X" + std::to_string(1 + (i + 1) % 2) + ". Y" + std::to_string(i + 1) + ".\n";
  // Absolute centres: each arc's centre is the origin, as I J give it (incremental puts it far off).
  text += "G03 X-1. Y-30000. I0 J0\nG01 X0 Y0\nM02\n";
  const Pipeline p = read(text);
  EXPECT_FALSE(p.diags.hasErrors()) << kerf::test::dump(p.diags);
  EXPECT_EQ(p.toolpath.reading.arcCentre, ArcCentreMode::Absolute);
  ASSERT_EQ(p.toolpath.moves.size(), 30003u);
  for (int i = 0; i < 30000; ++i) {
    const kerf::geometry::Vec2 end(1 + (i + 1) % 2, i + 1);
    ASSERT_EQ(p.toolpath.moves[static_cast<std::size_t>(i) + 1].lower.end, end) << "move " << i + 1;
  }
  EXPECT_EQ(p.toolpath.moves[30001].lower.centre, kerf::geometry::Vec2(0, 0));
  EXPECT_NEAR(p.toolpath.moves[30001].lower.radius(), std::hypot(1.0, 30000.0), 1e-9);
  EXPECT_EQ(p.toolpath.moves[30002].lower.end, kerf::geometry::Vec2(0, 0));

  // The G01 of line 2 is the motion word in force 30,000 blocks on: an arc that cannot be built
  // there points at the block, and a G02 missing its centre at the motion word of its own block.
  std::string bad = "G92 X0 Y0\nG01 X1. Y0\n";
  for (int i = 0; i < 30000; ++i) bad += "X" + std::to_string(1 + (i + 1) % 2) + ". Y" + std::to_string(i + 1) + ".\n";
  bad += "G02 X5. Y5.\nM02\n";
  const Pipeline q = read(bad);
  const Diagnostic& d = first(q, Code::ArcWithoutCentre);
  EXPECT_EQ(q.source->locate(d.span.offset).line, 30003u);
  EXPECT_EQ(q.source->text().substr(d.span.offset, d.span.length), "G02");

  // A G41 held 30,000 blocks (feeds, no move) until an arc carries it out: the message quotes
  // the word and its line, which are long gone from the parse tree by then.
  std::string held = "G92 X0 Y0\nG01 X5. Y0\n";
  for (int i = 0; i < 1000; ++i) held += "F2.\n";  // the G41 past the first pages
  held += "G41 D1\n";
  for (int i = 0; i < 30000; ++i) held += "F2.\n";
  held += "G03 X15. Y0 I5. J0\nM02\n";
  const Pipeline h = read(held);
  const Diagnostic& started = first(h, Code::OffsetOnArc);
  EXPECT_NE(started.message.find("(G41 on line 1003)"), std::string::npos) << started.message;
}

TEST(machine_test, a_code_the_profile_knows_is_a_note_and_others_stay_errors) {
  PipelineOptions robofil;
  robofil.read.machine = "robofil";
  const Pipeline known = read("G92\nG60\nG38\nG41 D0\nG01 X10. Y0\nG40\nM02\n", robofil);
  EXPECT_FALSE(known.diags.hasErrors()) << kerf::test::dump(known.diags);
  EXPECT_TRUE(has(known, Code::MachineCode));
  PipelineOptions generic;
  generic.read.machine = "generic";
  const Pipeline unknown = read("G92\nG60\nG01 X10. Y0\nM02\n", generic);
  EXPECT_TRUE(has(unknown, Code::UnknownGCode));
  EXPECT_TRUE(has(unknown, Code::SetPositionWithoutAxis));  // the bare G92 is Robofil's
  // The standard codes that do not move the wire are known everywhere.
  const Pipeline standard = read("G17 G21 G90 G94 G49 G61 G98\nG64\nG28 X Y\nG92 X0 Y0\nG01 X10.\nM02\n", generic);
  EXPECT_FALSE(standard.diags.hasErrors()) << kerf::test::dump(standard.diags);
  EXPECT_TRUE(has(standard, Code::HomePositionTaken));  // G28 homes the axes: to the profile's home, a note
  EXPECT_EQ(first(standard, Code::HomePositionTaken).severity, Severity::Note);
  EXPECT_FALSE(has(standard, Code::PositionUnknown));
}

// Issue 42: hot-wire programs home with `G28 X Y` and `G28 U V` (GRBL, LinuxCNC) and then cut in
// G91. The home is the profile's (default the origin): one note, the path drawn from there, and a
// profile that says `home = unknown` keeps the position to the machine. G53 alone moves nothing;
// G43/G44 (tool length) are known codes with no effect on the wire.
TEST(machine_test, g28_goes_to_the_profiles_home_and_the_path_after_it_is_drawn) {
  PipelineOptions o;
  o.read.machine = "generic";
  o.read.thickness = 100.0;
  const std::string foam =
      "G21\nG28 X Y\nG28 U V\nG91\nG1 X10 Y0 U10 V0 F300\nG1 X0 Y20 U0 V20\n"
      "G1 X-10 Y0 U-10 V0\nG1 X0 Y-20 U0 V-20\nG90\nG1 X5 Y5 U5 V5\nG28 X2 Y0\nM2\n";
  const Pipeline p = read(foam, o);
  EXPECT_FALSE(p.diags.hasErrors()) << kerf::test::dump(p.diags);
  EXPECT_FALSE(has(p, Code::PositionUnknown));
  ASSERT_TRUE(has(p, Code::HomePositionTaken));
  int notes = 0;
  for (const Diagnostic& d : p.diags.all()) notes += d.code == Code::HomePositionTaken;
  EXPECT_EQ(notes, 1);
  ASSERT_EQ(p.toolpath.moves.size(), 7u);                       // four sides, the move to (5, 5), through it and home
  EXPECT_NEAR(p.toolpath.moves[0].lower.end.x(), 10.0, 1e-12);  // from the home at the origin
  EXPECT_NEAR(p.toolpath.moves[3].lower.end.norm(), 0.0, 1e-12);
  EXPECT_EQ(p.toolpath.moves[5].kind, MoveKind::Rapid);  // G28 X2 Y0 in G90: through (2, 0) ...
  EXPECT_NEAR((p.toolpath.moves[5].lower.end - kerf::geometry::Vec2(2, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(p.toolpath.moves[6].kind, MoveKind::Rapid);  // ... home; U V named by none: stay
  EXPECT_NEAR(p.toolpath.moves[6].lower.end.norm(), 0.0, 1e-12);

  PipelineOptions u = o;
  u.read.machineFile = SourceText{"shop.profile", "name = shop\nhome = unknown\n"};
  const Pipeline unknown = read("G90 G92 X0 Y0\nG28 X Y\nG1 X10. Y0\nM2\n", u);
  EXPECT_TRUE(has(unknown, Code::PositionUnknown)) << kerf::test::dump(unknown.diags);
  EXPECT_FALSE(has(unknown, Code::HomePositionTaken));

  const Pipeline g53 = read("G43 Z100. H10\nG44 H2\nG49\nG90 G92 X0 Y0\nG53\nG1 X10. Y0\nX10. Y10.\nM2\n", o);
  EXPECT_FALSE(has(g53, Code::UnknownGCode)) << kerf::test::dump(g53.diags);
  EXPECT_FALSE(has(g53, Code::PositionUnknown)) << kerf::test::dump(g53.diags);
  EXPECT_EQ(g53.toolpath.moves.size(), 2u);
}

TEST(machine_test, a_profile_sets_the_limits_of_the_checks) {
  // A foam cutter's carriages are not limited like a wire guide (linuxcnc: 60 degrees).
  const std::string foam =
      "(AXIS,XY_Z_POS,0)\n(AXIS,UV_Z_POS,10)\nG0 X0 Y0 U0 V0\nG1 X10. Y0 U18. V0\nX10. Y10. U18. V10.\nM2\n";
  EXPECT_FALSE(read(foam).diags.hasErrors());
  PipelineOptions strict;
  strict.check.maxTaperDegrees = 30.0;
  EXPECT_TRUE(has(read(foam, strict), Code::TaperTooSteep));
}

TEST(machine_test, legacy_cnc3_numbering_gives_the_thickness) {
  // 15831944/cnc3 wrote M106 P<L> Q<H> and M107 P<T>; the current editor writes M100/M101 and uses
  // M106/M107 for the generator.
  const std::string body = "G92 X0 Y0 U0 V0\nG1 X10 Y0 G1 U11 V0\nG1 X10 Y10 G1 U10 V10\nM2\n";
  const Pipeline legacy = read("M106 P150 Q50\nM107 P30\n" + body);
  ASSERT_TRUE(legacy.toolpath.heights.known) << kerf::test::dump(legacy.diags);
  EXPECT_NEAR(legacy.toolpath.heights.planes.height(), 30.0, 1e-12);
  const Pipeline current = read("M106 P1\nM107 P30 Q8\n" + body);
  EXPECT_FALSE(current.toolpath.heights.known);
  EXPECT_TRUE(has(current, Code::HeightsMissing));
}

TEST(machine_test, sodick_header_reads_without_a_cascade) {
  const std::string text =
      "(      =    ON OFF  IP);\nC000   =   012 014 2215;\nH000   = +000000.0100  ;\n"
      "QAIC(2,1,0.1250,001.0,0.1650,0.0200,010.0,0016,0032,15,040);\nG80Y+;\nG83Y101;\nG00 XH111 + H112;\n"
      "Y-H113;\nG92 X10.0 Y5.0 Z0;\nTP29.8;\nTN27.8;\nG29;\nT94;\nT84;\nC000;\nA0 G41 H000 G01 X12.0 Y5.0;\n"
      "G01 X12.0 Y15.0;\nG02 X22.0 Y15.0 I5.0 J0;\nG01 X22.0 Y5.0;\nG01 X12.0 Y5.0;\nG01 G40 H000 X10.0 Y5.0;\n"
      "T85;\nG149 G249;\nM199;\n";
  const Pipeline p = read(text);
  EXPECT_EQ(p.machine.name, "sodick");
  EXPECT_FALSE(p.diags.hasErrors()) << kerf::test::dump(p.diags);
  // The edge sensing and the register moves are one note, ended by the G92.
  const auto unknown = std::count_if(p.diags.all().begin(), p.diags.all().end(),
                                     [](const Diagnostic& d) { return d.code == Code::PositionUnknown; });
  EXPECT_EQ(unknown, 1);
  // 6 programmed moves and, with H000 = 0.01 applied, one arc round the convex corner at (22, 5).
  EXPECT_EQ(p.toolpath.moves.size(), 7u);
  EXPECT_TRUE(p.toolpath.endedProperly);  // M199
}

TEST(machine_test, a_detected_sodick_program_is_parsed_again_with_its_block_ends) {
  // Two blocks on one line: read first with ';' as a comment, the second is lost; the
  // detected profile ends blocks at ';', so the text is parsed again and both are there.
  const SourceFile src("p.nc", "C000 = 012 014;\nH000 = +000000.0100 ;\nG92 X0 Y0;\nG01 X5.; Y5.;\nM02;\n");
  const MachineReading detected = readForMachine(src, nullptr);
  ASSERT_NE(detected.machine, nullptr);
  EXPECT_EQ(detected.machine->name, "sodick");
  EXPECT_FALSE(detected.detection.evidence.empty());
  EXPECT_TRUE(detected.parse.semicolonEndsBlock);
  const MachineReading asGeneric = readForMachine(src, findBuiltinMachine("generic"));
  EXPECT_EQ(asGeneric.machine->name, "generic");
  EXPECT_TRUE(asGeneric.detection.evidence.empty());
  EXPECT_EQ(detected.program.blocks.size(), asGeneric.program.blocks.size() + 1);
  // --upper-axes wins over the profile's reading.
  EXPECT_TRUE(readForMachine(src, nullptr, true).parse.upperAxesUZ);
}

TEST(machine_test, a_cut_from_a_register_value_is_an_error_once) {
  const Pipeline p = read("G92 X0 Y0\nG01 XH111 Y0\nX5. YH2\nX20. Y10.\nX0 Y0\nM02\n");
  const auto errors = std::count_if(p.diags.all().begin(), p.diags.all().end(), [](const Diagnostic& d) {
    return d.code == Code::PositionUnknown && d.severity == Severity::Error;
  });
  EXPECT_EQ(errors, 1);
  EXPECT_NE(first(p, Code::PositionUnknown).message.find("lines 2 to 4 (3 cut)"), std::string::npos)
      << first(p, Code::PositionUnknown).message;
}

}  // namespace

TEST(machine_test, a_rapid_between_cuts_is_a_new_start_hole_where_the_wire_may_be_rethreaded) {
  PipelineOptions generic;
  generic.read.machine = "generic";
  const std::string cuts = "G92 X0 Y0\nG01 X10. Y0\nX10. Y10.\nX0 Y0\n";
  const std::string next = "G00 X20. Y0\n";
  const std::string more = "G01 X30. Y0\nX30. Y10.\nX20. Y0\nM02\n";
  auto severityOfRapid = [&](const std::string& text, PipelineOptions o) {
    const Pipeline p = read(text, o);
    return has(p, Code::RapidInsideCut) ? first(p, Code::RapidInsideCut).severity : Severity::Error;
  };
  // Bare: a point-driven machine would cut along it.
  EXPECT_EQ(severityOfRapid(cuts + next + more, generic), Severity::Warning);
  // An M00 or M01 on either side of the rapid: the operator cuts and threads the wire there.
  EXPECT_EQ(severityOfRapid(cuts + "M00\n" + next + more, generic), Severity::Note);
  EXPECT_EQ(severityOfRapid(cuts + next + "M01\n" + more, generic), Severity::Note);
  // A stop before an earlier cut does not count.
  EXPECT_EQ(severityOfRapid("G92 X0 Y0\nM00\nG01 X10. Y0\nX10. Y10.\nX0 Y0\n" + next + more, generic),
            Severity::Warning);
  // A profile's own rethread code counts as the stop does.
  PipelineOptions own;
  own.read.machineFile = SourceText{
      "awt.profile", "name = awt\nsummary = automatic threading\ncode M60 = rethread: cut and thread the wire\n"};
  EXPECT_EQ(severityOfRapid(cuts + "M60\n" + next + more, own), Severity::Note);
  // With G41 applied (moves inserted), the stop keeps its place between the contours.
  PipelineOptions offset = generic;
  offset.read.wireOffset = 0.1;
  EXPECT_EQ(severityOfRapid("G92 X-2 Y0\nG41 G01 X0 Y0\nX10. Y0\nX10. Y10.\nX0 Y0\nG40 G01 X-2 Y0\nM00\n" + next +
                                "M00\nG01 X30. Y0\nX30. Y10.\nX20. Y0\nM02\n",
                            offset),
            Severity::Note);
}

TEST(machine_test, between_contours_the_iso_writer_cuts_and_threads_the_wire_as_the_profile_says) {
  PipelineOptions generic;
  generic.read.machine = "generic";
  const Pipeline two =
      read("G92 X0 Y0\nG01 X10. Y0\nX10. Y10.\nX0 Y0\nG00 X20. Y0\nG01 X30. Y0\nX30. Y10.\nX20. Y0\nM02\n", generic);
  auto written = [&](const MachineProfile& target) {
    EmitRequest request;
    request.iso.target = &target;
    Diagnostics d(100);
    const std::optional<EmitOutput> out = findEmitter("iso")->write(two.toolpath, two.source.get(), request, d);
    return out ? out->text : std::string();
  };
  // The generic profile: M00 before the rapid and after it (the operator's stop).
  const std::string g = written(*findBuiltinMachine("generic"));
  EXPECT_NE(g.find("X0.000 Y0.000\nM00\nG00 X20.000 Y0.000\nM00\nG01 X30.000"), std::string::npos) << g;
  // A machine's own codes, and none at all.
  const SourceFile file(
      "awt.profile",
      "name = awt\nsummary = automatic threading\nwrite_wire_cut = M50\nwrite_wire_thread = M60 | G04 "
      "P1\n");
  Diagnostics d(10);
  const std::optional<MachineProfile> awt = parseMachineProfile(file, d);
  ASSERT_TRUE(awt) << kerf::test::dump(d);
  const std::string a = written(*awt);
  EXPECT_NE(a.find("\nM50\nG00 X20.000 Y0.000\nM60\nG04 P1\nG01 X30.000"), std::string::npos) << a;
  const SourceFile none("none.profile", "name = none\nsummary = x\nwrite_wire_cut =\nwrite_wire_thread =\n");
  const std::optional<MachineProfile> bare = parseMachineProfile(none, d);
  ASSERT_TRUE(bare) << kerf::test::dump(d);
  EXPECT_EQ(written(*bare).find("M00"), std::string::npos);
}

// The checks run on several cores (the sweep's boxes and pair tests in batches, the closure's
// probes when it needs its table): what they say, and its order, is what one thread says, the open path's warning
// before the crossings on the same move included.
TEST(machine_test, the_checks_say_the_same_in_the_same_order_on_one_thread_and_on_many) {
  std::string text = "G92 X0 Y0\nG01 X1 Y0\nG00 X2 Y0\nG01 X2 Y1\n";
  for (int k = 0; k < 20; ++k)  // a zigzag up, then one move down across it: crossings, never closed
    text += "G01 X" + std::to_string(3 + k % 2 * 40) + " Y" + std::to_string(2 + k) + "\n";
  text += "G01 X20 Y0\nM02\n";
  auto listed = [&](unsigned threads) {
    const kerf::test::ScopedThreads scoped(threads);
    const Pipeline p = read(text);
    std::vector<std::string> out;
    for (const Diagnostic& d : p.diags.all())
      out.push_back(std::string(codeName(d.code)) + " @" + std::to_string(d.span.offset) + " " + d.message);
    return out;
  };
  const std::vector<std::string> one = listed(1);
  auto count = [&](Code c) {
    return std::count_if(one.begin(), one.end(), [&](const std::string& s) { return s.starts_with(codeName(c)); });
  };
  EXPECT_EQ(count(Code::PathOpen), 1);
  EXPECT_EQ(count(Code::RapidInsideCut), 1);
  EXPECT_GT(count(Code::PathCrossesItself), 15);
  // The crossings are all on the last move, where the closure's warning is too (a tie in
  // position): that warning comes first, as the checks report them.
  const auto open = std::find_if(one.begin(), one.end(),
                                 [](const std::string& s) { return s.starts_with(codeName(Code::PathOpen)); });
  ASSERT_NE(open, one.end());
  const std::string at = open->substr(open->find('@'), open->find(' ', open->find('@')) - open->find('@'));
  const auto crossing = std::find_if(one.begin(), one.end(), [&](const std::string& s) {
    return s.starts_with(codeName(Code::PathCrossesItself)) && s.find(at + " ") != std::string::npos;
  });
  ASSERT_NE(crossing, one.end());
  EXPECT_LT(open, crossing);
  for (const unsigned threads : {2u, 4u}) EXPECT_EQ(listed(threads), one) << threads << " threads";
}

// Plain blocks (X Y I J R F and G00-G03 only) take a short way through the interpreter
// (interpreter.cpp): what it cannot judge goes the general way and is said as before, and a profile that
// gives G01 a meaning of its own closes the short way.
TEST(machine_test, plain_blocks_say_what_every_block_says) {
  EXPECT_TRUE(has(read("G92 X0 Y0\nG01 X1. X2.\nM02\n"), Code::RepeatedWord));
  EXPECT_TRUE(has(read("G92 X0 Y0\nG01 G02 X1.\nM02\n"), Code::ModalGroupConflict));
  EXPECT_TRUE(has(read("G92 X0 Y0\nG01 X1. F0\nM02\n"), Code::BadFeed));
  EXPECT_TRUE(has(read("G92 X0 Y0\nX1. Y1.\nM02\n"), Code::NoMotionMode));
  EXPECT_TRUE(has(read("G92 X0 Y0\nG01 X1. R2.\nM02\n"), Code::CentreOnStraightMove));
  EXPECT_TRUE(has(read("G92 X0 Y0\nG02 X1. Y0 R0.1\nM02\n"), Code::RadiusTooSmall));
  const Pipeline feeds = read("G92 X0 Y0\nG01 X1. F2.\nG01 X2. F3.\nX3. F2.\nM02\n");
  ASSERT_EQ(feeds.toolpath.moves.size(), 3u);
  auto feed = [&](std::size_t i) { return feeds.toolpath.feedOf(i); };
  EXPECT_EQ(feed(0), 2.0);
  EXPECT_EQ(feed(1), 3.0);
  EXPECT_EQ(feed(2), 2.0);
  PipelineOptions own;
  own.read.machineFile = SourceText{"g1.profile", "name = g1\ncode G01 = rethread: cut and thread the wire\n"};
  const Pipeline p = read("G92 X0 Y0\nG00 X1. Y0\nG01\nG00 X2. Y0\nM02\n", own);
  EXPECT_EQ(first(p, Code::MachineCode).message, "G01: cut and thread the wire [g1 profile]");  // not a motion
  EXPECT_TRUE(std::all_of(p.toolpath.moves.begin(), p.toolpath.moves.end(),
                          [](const Move& m) { return m.kind == MoveKind::Rapid; }));
}

TEST(machine_test, offset_registers_are_named_as_the_program_names_them) {
  EXPECT_EQ(kerf::converter::offsetRegisterName("H1"), "H001");
  EXPECT_EQ(kerf::converter::offsetRegisterName(" d012 "), "D012");
  EXPECT_EQ(kerf::converter::offsetRegisterName("H 7"), "H007");
  EXPECT_EQ(kerf::converter::offsetRegisterName("X1"), "");
  EXPECT_EQ(kerf::converter::offsetRegisterName("H1000"), "");
  EXPECT_EQ(kerf::converter::offsetRegisterName("H1.5"), "");
}

TEST(machine_test, an_offset_table_file_is_read_and_its_wrong_lines_reported_at_their_place) {
  using kerf::converter::readOffsetTable;
  {
    SourceFile file("t.offsets", "# skims\nH001 = 0.180\nh2=0.11   # second\n\nD1 = 0.15\n");
    Diagnostics d;
    const auto table = readOffsetTable(file, d);
    ASSERT_TRUE(table.has_value()) << kerf::test::dump(d);
    EXPECT_EQ(table->size(), 3u);
    EXPECT_EQ(table->at("H002"), 0.11);
    EXPECT_EQ(table->at("D001"), 0.15);
  }
  SourceFile file("t.offsets", "H001 = 0.180\nH001 = 0.2\nX3 = 1\nH4 = 12\nH5 = abc\nH6 0.1\n");
  Diagnostics d;
  EXPECT_FALSE(readOffsetTable(file, d).has_value());
  ASSERT_EQ(d.errorCount(), 5u) << kerf::test::dump(d);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(d.all()[k].code, Code::OffsetTableError);
    EXPECT_EQ(file.locate(d.all()[k].span.offset).line, k + 2) << d.all()[k].message;
  }
}

TEST(machine_test, a_profile_gives_offset_registers) {
  SourceFile file("m.profile", "name = shop\noffset H001 = 0.18\noffset H1 = 0.2\noffset H2 = -1\n");
  Diagnostics d;
  EXPECT_FALSE(parseMachineProfile(file, d).has_value());
  ASSERT_EQ(d.errorCount(), 2u) << kerf::test::dump(d);  // H001 twice; a negative offset
  SourceFile good("m.profile", "name = shop\noffset H001 = 0.18\noffset D3 = 0.2\n");
  Diagnostics g;
  const auto p = parseMachineProfile(good, g);
  ASSERT_TRUE(p.has_value()) << kerf::test::dump(g);
  EXPECT_EQ(p->offsets.at("H001"), 0.18);
  EXPECT_EQ(p->offsets.at("D003"), 0.2);
}

// The speed model of the time estimate (docs/passes.md): the generic profile's assumptions, a
// profile's own numbers, LinuxCNC's F as the speed, and wrong values refused at their line.
TEST(machine_test, a_profile_gives_the_speed_model) {
  const MachineProfile* generic = findBuiltinMachine("generic");
  ASSERT_NE(generic, nullptr);
  EXPECT_EQ(generic->speeds.roughRate, 100.0);
  EXPECT_EQ(generic->speeds.skimSpeed, 10.0);
  EXPECT_EQ(generic->speeds.rapidSpeed, 1000.0);
  EXPECT_EQ(generic->speeds.threadSeconds, 30.0);
  EXPECT_FALSE(generic->speeds.feedIsSpeed);
  ASSERT_NE(findBuiltinMachine("linuxcnc"), nullptr);
  EXPECT_TRUE(findBuiltinMachine("linuxcnc")->speeds.feedIsSpeed);
  SourceFile good("m.profile",
                  "name = shop\nrough_rate = 250\nskim_speed = 12.5\nrapid_speed = 3000\n"
                  "thread_time = 0\nfeed = speed\n");
  Diagnostics g;
  const auto p = parseMachineProfile(good, g);
  ASSERT_TRUE(p.has_value()) << kerf::test::dump(g);
  EXPECT_EQ(p->speeds.roughRate, 250.0);
  EXPECT_EQ(p->speeds.skimSpeed, 12.5);
  EXPECT_EQ(p->speeds.rapidSpeed, 3000.0);
  EXPECT_EQ(p->speeds.threadSeconds, 0.0);
  EXPECT_TRUE(p->speeds.feedIsSpeed);
  SourceFile bad("m.profile", "name = shop\nrough_rate = 0\nskim_speed = fast\nthread_time = -1\nfeed = yes\n");
  Diagnostics b;
  EXPECT_FALSE(parseMachineProfile(bad, b).has_value());
  ASSERT_EQ(b.errorCount(), 4u) << kerf::test::dump(b);
  EXPECT_EQ(bad.locate(b.all()[0].span.offset).line, 2u);
}

// `condition_speed C001 = 4`: a speed a machining condition, named in any case; wrong names,
// values and repeats refused at their line. The built-in sodick profile's C selects a condition.
TEST(machine_test, a_profile_gives_its_conditions_speeds) {
  SourceFile good("m.profile", "name = shop\ncondition_speed C001 = 4\ncondition_speed c2 = 12.5\n");
  Diagnostics g;
  const auto p = parseMachineProfile(good, g);
  ASSERT_TRUE(p.has_value()) << kerf::test::dump(g);
  EXPECT_EQ(p->speeds.conditionSpeeds.at("C001"), 4.0);
  EXPECT_EQ(p->speeds.conditionSpeeds.at("C2"), 12.5);
  SourceFile bad("m.profile",
                 "name = shop\ncondition_speed 12 = 4\ncondition_speed C1 = 0\n"
                 "condition_speed C2 = 3\ncondition_speed c2 = 4\n");
  Diagnostics b;
  EXPECT_FALSE(parseMachineProfile(bad, b).has_value());
  ASSERT_EQ(b.errorCount(), 3u) << kerf::test::dump(b);
  EXPECT_EQ(bad.locate(b.all()[2].span.offset).line, 5u);
  const MachineProfile* sodick = findBuiltinMachine("sodick");
  ASSERT_NE(sodick, nullptr);
  ASSERT_NE(sodick->find("C"), nullptr);
  EXPECT_EQ(sodick->find("C")->effect, CodeEffect::Condition);
}

// A code whose number is too long to be one is refused at its line, never cast (the profile fuzzer
// found `code G111111111111111 = ...` and `code Q2222...AIC = ...` cast to int: undefined behaviour).
TEST(machine_test, a_code_number_of_seven_digits_is_no_code) {
  SourceFile bad("m.profile",
                 "name = shop\ncode G111111111111111 = harmless: no such code\ncode G999999 = harmless: x\n"
                 "code Q22222222222222222222AIC = harmless: a macro name that reads as a number\n");
  Diagnostics b;
  EXPECT_FALSE(parseMachineProfile(bad, b).has_value());
  ASSERT_EQ(b.errorCount(), 2u) << kerf::test::dump(b);
  EXPECT_EQ(bad.locate(b.all()[0].span.offset).line, 2u);
  EXPECT_EQ(bad.locate(b.all()[1].span.offset).line, 4u);
}

// A write_* block with a placeholder its key does not fill is refused at its line (issue 41: a
// user profile's `{offset}` inside write_offset was written into the program as it stood).
TEST(machine_test, write_blocks_take_only_the_placeholders_they_fill) {
  SourceFile bad("m.profile",
                 "name = shop\nwrite_offset = {g} D1 {offset}\nwrite_start = G90 | {cancel}\nwrite_end = M02 {g}\n");
  Diagnostics b;
  EXPECT_FALSE(parseMachineProfile(bad, b).has_value());
  ASSERT_EQ(b.errorCount(), 3u) << kerf::test::dump(b);
  SourceFile good("m.profile",
                  "name = shop\nwrite_offset = {g} D1 X{x} Y{y}\nwrite_start = G90 | {offset}\n"
                  "write_end = {cancel} | M02\nwrite_cancel = {g}\n");
  Diagnostics g;
  EXPECT_TRUE(parseMachineProfile(good, g).has_value()) << kerf::test::dump(g);
}
