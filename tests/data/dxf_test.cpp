// Every DXF drawing in ../shared/realworld/dxf read by Kerf (`kerf check FILE --json`) and by
// ezdxf (tests/tools/dxf_oracle.py, Debian's python3-ezdxf and python3-shapely: an independent
// reader): the model-space entity counts by type must be equal, the total length of the contour
// geometry (INSERTs expanded, bulges, splines and ellipses) equal within what ezdxf's flattening of
// curves can lose (it states the bound), and where no node joins
// more than two ends, the chaining must agree too — as many contours, as many closed, and the
// closed ones enclosing the same areas.
#include "data_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string run(const std::string& command, const fs::path& out, int& exit) {
  const int status = std::system((command + " > '" + out.string() + "'").c_str());
  exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return kerf::test::readFile(out);
}

// Issue 41: kerf cam that refuses to write (its program crosses itself when read back) names the
// program it made, not the output file it did not write. The part: a limaçon with its inner loop
// (r = 10 + 20 cos t), whose curve crosses itself at the origin; with the offset left to the
// controller the program cuts the curve as drawn, so the program made crosses itself (K0601).
TEST(cam_test, a_refused_program_is_named_as_not_written) {
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  const fs::path out = work / "refused.nc";
  fs::remove(out);
  int exit = 0;
  const std::string err =
      run("('" + std::string(KERF_PROGRAM) +
              "' cam --curve 'x = (10+20*cos(t))*cos(t); y = (10+20*cos(t))*sin(t)' --t 0:2*pi --offset-by controller "
              "-o '" +
              out.string() + "' 2>&1)",
          work / "refused.log", exit);
  EXPECT_EQ(exit, 1) << err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(err.find("<not written: " + out.string() + ">:42:1: error: the cut path crosses itself at (0.000, 0.000)"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find(out.string() + ":"), std::string::npos) << "a line of a file that is not there: " << err;
}

// Issue 43: samples/plate.dxf's three contours as kerf cam makes them with the offset left to the
// controller (G42), then two mistakes a programmer makes by hand: the round hole forgotten, and one
// corner of the square typed 10 um off (X31.010 for X31.000). The program against its drawing finds
// both, at their lines, with the deviation; the program as made finds nothing.
TEST(drawing_test, a_forgotten_hole_and_a_mistyped_corner_are_found_against_the_drawing) {
  const std::string made =
      "G90 G21\nG92 X15.000 Y15.000\nG42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000 J0.000\nM00\n"
      "G40 G00 X26.414 Y11.414\nM00\nG42 G01 X25.000 Y10.000\nG01 X25.000 Y20.000\nG01 X31.000 Y20.000\n"
      "G01 X31.000 Y10.000\nG01 X25.000 Y10.000\nM00\nG40 G00 X4.000 Y-2.000\nM00\nG42 G01 X4.000 Y0.000\n"
      "G01 X36.000 Y0.000\nG03 X40.000 Y4.000 I0.000 J4.000\nG01 X40.000 Y26.000\nG03 X36.000 Y30.000 I-4.000 "
      "J0.000\nG01 X4.000 Y30.000\nG03 X0.000 Y26.000 I0.000 J-4.000\nG01 X0.000 Y4.000\nG03 X4.000 Y0.000 "
      "I4.000 J0.000\nG40\nM02\n";
  std::string wrong = made;
  wrong.replace(wrong.find("G42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000 J0.000\n"),
                std::string("G42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000 J0.000\n").size(), "");
  wrong.replace(wrong.find("G01 X31.000 Y20.000"), 19, "G01 X31.010 Y20.000");
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  const std::string drawing = std::string(KERF_SAMPLES_DIR) + "/plate.dxf";
  auto check = [&](const std::string& name, const std::string& text, int& exit) {
    kerf::test::writeFile(work / name, text);
    return json::parse(run("'" + std::string(KERF_PROGRAM) + "' check --json '" + (work / name).string() +
                               "' --drawing '" + drawing + "' 2>/dev/null",
                           work / (name + ".json"), exit));
  };
  int exit = 0;
  const json good = check("plate_made.nc", made, exit);
  EXPECT_EQ(exit, 0);
  const json& c = good["summary"]["comparison"];
  EXPECT_EQ(c["out_of_tolerance"], 0);
  EXPECT_LE(c["worst_mm"].get<double>(), 1e-6) << c.dump();
  EXPECT_EQ(c["elements"].size(), 13u);
  const json bad = check("plate_wrong.nc", wrong, exit);
  EXPECT_EQ(exit, 1);
  bool holeNotCut = false, cornerOff = false;
  for (const json& d : bad["diagnostics"]) {
    holeNotCut |= d["code"] == "K0631" && d["message"].get<std::string>().find("(12.000, 15.000)") != std::string::npos;
    if (d["code"] == "K0630" && d["line"] == 9) {  // the block down from the mistyped corner, nearest the far point
      cornerOff = true;
      EXPECT_NE(d["message"].get<std::string>().find("9.9 µm off"), std::string::npos) << d.dump();
    }
  }
  EXPECT_TRUE(holeNotCut) << bad["diagnostics"].dump(1);
  EXPECT_TRUE(cornerOff) << bad["diagnostics"].dump(1);
}

// Issue 43's twins of one program: samples/plate.dxf as kerf cam makes it for the controller to
// offset (G42), each with one mistake a programmer makes, checked through kerf against the drawing.
// Each is found at its line with its deviation, or, for a part turned or mirrored, named.
class drawing_twins_test : public testing::Test {
 protected:
  static std::string made() {
    return "G90 G21\nG92 X15.000 Y15.000\nG42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000 J0.000\nM00\n"
           "G40 G00 X26.414 Y11.414\nM00\nG42 G01 X25.000 Y10.000\nG01 X25.000 Y20.000\nG01 X31.000 Y20.000\n"
           "G01 X31.000 Y10.000\nG01 X25.000 Y10.000\nM00\nG40 G00 X4.000 Y-2.000\nM00\nG42 G01 X4.000 Y0.000\n"
           "G01 X36.000 Y0.000\nG03 X40.000 Y4.000 I0.000 J4.000\nG01 X40.000 Y26.000\nG03 X36.000 Y30.000 I-4.000 "
           "J0.000\nG01 X4.000 Y30.000\nG03 X0.000 Y26.000 I0.000 J-4.000\nG01 X0.000 Y4.000\nG03 X4.000 Y0.000 "
           "I4.000 J0.000\nG40\nM02\n";
  }
  static std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
  }
  /// kerf check NAME --drawing plate.dxf OPTIONS --json: the report, and the exit status.
  json check(const std::string& name, const std::string& text, const std::string& options, int& exit) const {
    const fs::path work = fs::path(KERF_DXF_WORK);
    fs::create_directories(work);
    kerf::test::writeFile(work / name, text);
    return json::parse(run("'" + std::string(KERF_PROGRAM) + "' check --json '" + (work / name).string() +
                               "' --drawing '" + std::string(KERF_SAMPLES_DIR) + "/plate.dxf' " + options +
                               " 2>/dev/null",
                           work / (name + ".json"), exit));
  }
  /// The diagnostics of one code, on one line (0: any line).
  static std::vector<json> findings(const json& report, const std::string& code, int line = 0) {
    std::vector<json> out;
    for (const json& d : report["diagnostics"])
      if (d["code"] == code && (line == 0 || d["line"] == line)) out.push_back(d);
    return out;
  }
  static bool says(const json& d, const std::string& words) {
    return d["message"].get<std::string>().find(words) != std::string::npos;
  }
};

TEST_F(drawing_twins_test, an_arc_radius_0_02_mm_too_large_is_found_at_its_block_20_um_off) {
  int exit = 0;
  const json r = check("twin_radius.nc",
                       replaced(made(), "G42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000",
                                "G42 G01 X17.020 Y15.000\nG02 X17.020 Y15.000 I-5.020"),
                       "", exit);
  EXPECT_EQ(exit, 1);
  const auto off = findings(r, "K0630", 4);
  ASSERT_EQ(off.size(), 1u) << r["diagnostics"].dump(1);
  EXPECT_TRUE(says(off[0], "20.0 µm off")) << off[0].dump();
  EXPECT_NEAR(r["summary"]["comparison"]["worst_mm"].get<double>(), 0.020, 1e-6);
}

TEST_F(drawing_twins_test, a_line_moved_0_05_mm_is_found_at_its_block) {
  int exit = 0;
  const json r = check("twin_line.nc",
                       replaced(replaced(made(), "G01 X31.000 Y20.000", "G01 X31.050 Y20.000"), "G01 X31.000 Y10.000",
                                "G01 X31.050 Y10.000"),
                       "", exit);
  EXPECT_EQ(exit, 1);
  const auto off = findings(r, "K0630", 11);
  ASSERT_EQ(off.size(), 1u) << r["diagnostics"].dump(1);
  EXPECT_TRUE(says(off[0], "50.0 µm off")) << off[0].dump();
  EXPECT_EQ(r["summary"]["comparison"]["out_of_tolerance"], 1);
}

TEST_F(drawing_twins_test, a_part_mirrored_or_turned_is_named) {
  // x -> -x: X and I change sign, G02 and G03 change places, and G42 becomes G41.
  std::string mirrored = std::regex_replace(made(), std::regex("([XI])(-?)([0-9])"), "$1-$2$3");
  mirrored = std::regex_replace(mirrored, std::regex("--"), "");
  mirrored = std::regex_replace(mirrored, std::regex("G02"), "G0x");
  mirrored = std::regex_replace(mirrored, std::regex("G03"), "G02");
  mirrored = std::regex_replace(mirrored, std::regex("G0x"), "G03");
  mirrored = std::regex_replace(mirrored, std::regex("G42"), "G41");
  int exit = 0;
  const json r = check("twin_mirrored.nc", mirrored, "", exit);
  EXPECT_EQ(exit, 1);
  const auto named = findings(r, "K0634");
  ASSERT_EQ(named.size(), 1u) << r["diagnostics"].dump(1);
  EXPECT_TRUE(says(named[0], "mirrored left to right (x -> -x)")) << named[0].dump();
  EXPECT_TRUE(findings(r, "K0630").empty()) << "the mirror explains every element: said once";
  // The drawing placed 5 mm left and 3 mm up of the part (--drawing-origin 5,-3): named without
  // --align, taken with it.
  const json named2 = check("twin_placed.nc", made(), "--drawing-origin 5,-3", exit);
  EXPECT_EQ(exit, 1);
  ASSERT_EQ(findings(named2, "K0634").size(), 1u) << named2["diagnostics"].dump(1);
  EXPECT_TRUE(says(findings(named2, "K0634")[0], "shifted by (5.0000, -3.0000) mm")) << named2["diagnostics"].dump(1);
  const json aligned = check("twin_placed.nc", made(), "--drawing-origin 5,-3 --align", exit);
  EXPECT_EQ(exit, 0) << aligned["diagnostics"].dump(1);
  EXPECT_EQ(findings(aligned, "K0634").size(), 1u) << "a note naming the placement";
  EXPECT_LE(aligned["summary"]["comparison"]["worst_mm"].get<double>(), 1e-6);
}

TEST_F(drawing_twins_test, a_hole_left_out_is_not_cut) {
  int exit = 0;
  const json r =
      check("twin_hole.nc", replaced(made(), "G42 G01 X17.000 Y15.000\nG02 X17.000 Y15.000 I-5.000 J0.000\nM00\n", ""),
            "", exit);
  EXPECT_EQ(exit, 1);
  const auto uncut = findings(r, "K0631");
  ASSERT_EQ(uncut.size(), 1u) << r["diagnostics"].dump(1);
  EXPECT_TRUE(says(uncut[0], "around (12.000, 15.000)"));
  EXPECT_TRUE(findings(r, "K0630").empty()) << r["diagnostics"].dump(1);
}

// The outline's wire path at 0.15 mm written with G42 again: the offset is applied twice, and the
// whole contour is off by 0.15 mm, said once. Moved back as a wire path (no G42, --offset 0.15),
// the same moves are the drawing's outline.
TEST_F(drawing_twins_test, an_offset_applied_twice_and_a_wire_path_moved_back) {
  const std::string outline =
      "G01 X4.000 Y-0.150\nG01 X36.000 Y-0.150\nG03 X40.150 Y4.000 I0.000 J4.150\nG01 X40.150 Y26.000\n"
      "G03 X36.000 Y30.150 I-4.150 J0.000\nG01 X4.000 Y30.150\nG03 X-0.150 Y26.000 I0.000 J-4.150\n"
      "G01 X-0.150 Y4.000\nG03 X4.000 Y-0.150 I4.150 J0.000\n";
  int exit = 0;
  const json twice = check("twin_twice.nc", "G90 G21\nG92 X4.000 Y-2.000\nG42 " + outline + "G40\nM02\n", "", exit);
  EXPECT_EQ(exit, 1);
  bool sideways = false;
  for (const json& d : findings(twice, "K0630"))
    sideways |= says(d, "(8 elements) is cut 150.0 µm to 150.0 µm off: the cut is the contour moved sideways");
  EXPECT_TRUE(sideways) << twice["diagnostics"].dump(1);
  const json wire =
      check("twin_wire.nc", "G90 G21\nG92 X4.000 Y-2.000\n" + outline + "M02\n", "--offset 0.15 --side outside", exit);
  EXPECT_EQ(findings(wire, "K0633").size(), 1u) << wire["diagnostics"].dump(1);
  EXPECT_EQ(findings(wire, "K0630").size(), 0u) << wire["diagnostics"].dump(1);
  EXPECT_EQ(findings(wire, "K0631").size(), 2u) << "the two holes are not in this program";
  double outlineWorst = 0.0;
  for (const json& e : wire["summary"]["comparison"]["elements"])
    if (e["drawing_line"] == 1771) outlineWorst = std::max(outlineWorst, e["deviation_mm"].get<double>());
  EXPECT_LE(outlineWorst, 1e-6) << wire["summary"]["comparison"].dump();
}

// --color-by deviation draws what --drawing measured: without a drawing there is nothing to colour.
TEST_F(drawing_twins_test, colour_by_deviation_needs_a_drawing) {
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  kerf::test::writeFile(work / "plate_made.nc", made());
  int exit = 0;
  const std::string err = run("('" + std::string(KERF_PROGRAM) + "' render '" + (work / "plate_made.nc").string() +
                                  "' --color-by deviation -o '" + (work / "no.png").string() + "' 2>&1)",
                              work / "no_drawing.log", exit);
  EXPECT_EQ(exit, 2) << err;
  EXPECT_NE(err.find("--color-by deviation needs --drawing"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(work / "no.png"));
}

// kerf export with --drawing: the drawing's elements out of tolerance on a DXF layer DEVIATION (the
// mistyped circle, and nothing else), and a cell array "deviation" in the VTP.
TEST_F(drawing_twins_test, export_writes_the_deviation_layer_and_array) {
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  const std::string program = std::string(KERF_SOURCE_DIR) + "/tests/drawing/plate_radius_off.nc";
  const std::string drawing = std::string(KERF_SAMPLES_DIR) + "/plate.dxf";
  for (const char* name : {"deviation.dxf", "deviation.vtp"}) {
    fs::remove(work / name);
    int exit = 0;
    run("'" + std::string(KERF_PROGRAM) + "' export '" + program + "' --drawing '" + drawing + "' -o '" +
            (work / name).string() + "' 2>/dev/null",
        work / "export.log", exit);
    EXPECT_EQ(exit, 1) << name << ": the program has an error against its drawing";
  }
  // DXF group pairs: code, then value, CRLF line ends. The entities on layer DEVIATION, by type.
  const std::string dxf = kerf::test::readFile(work / "deviation.dxf");
  std::vector<std::string> lines;
  for (std::size_t at = 0, next; at < dxf.size(); at = next + 1) {
    next = dxf.find('\n', at);
    if (next == std::string::npos) next = dxf.size();
    std::string l = dxf.substr(at, next - at);
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(l.erase(0, l.find_first_not_of(' ')));
  }
  std::vector<std::string> onLayer;
  std::string entity;
  for (std::size_t k = 0; k + 1 < lines.size(); k += 2) {
    if (lines[k] == "0") entity = lines[k + 1];
    if (lines[k] == "8" && lines[k + 1] == "DEVIATION" && entity != "LAYER") onLayer.push_back(entity);
  }
  EXPECT_EQ(onLayer, std::vector<std::string>{"CIRCLE"});
  EXPECT_NE(kerf::test::readFile(work / "deviation.vtp").find("Name=\"deviation\""), std::string::npos);
}

// A taper part (XYUV, a 20 mm square below, 18 mm above) against a drawing of both planes on two
// layers, made by kerf export from the contour alone: the part as drawn fits both planes; with its
// upper plane turned 1 degree about the centre, the lower plane still fits and the upper plane's
// drawing is named turned by 1 degree.
TEST_F(drawing_twins_test, a_taper_part_with_its_upper_plane_turned_1_degree) {
  const fs::path work = fs::path(KERF_DXF_WORK);
  fs::create_directories(work);
  const std::string square = "G01 X10 Y-10 U9 V-9\nG01 X10 Y10 U9 V9\nG01 X-10 Y10 U-9 V9\nG01 X-10 Y-10 U-9 V-9\n";
  kerf::test::writeFile(work / "taper_drawing.nc",
                        "G90 G21\nG92 X0 Y-10 U0 V-9\n" + square + "G01 X0 Y-10 U0 V-9\nM02\n");
  int exit = 0;
  run("'" + std::string(KERF_PROGRAM) + "' export '" + (work / "taper_drawing.nc").string() + "' -o '" +
          (work / "taper.dxf").string() + "' --thickness 20 2>/dev/null",
      work / "taper_export.log", exit);
  ASSERT_EQ(exit, 0);
  // The upper plane turned 1 degree: (u, v) -> (u cos 1 - v sin 1, u sin 1 + v cos 1), 4 decimals.
  const std::string turned =
      "G01 X10 Y-10 U9.1557 V-8.8416\nG01 X10 Y10 U8.8416 V9.1557\nG01 X-10 Y10 U-9.1557 "
      "V8.8416\nG01 X-10 Y-10 U-8.8416 V-9.1557\nG01 X0 Y-10 U0.1571 V-8.9986\n";
  auto check = [&](const std::string& name, const std::string& contour) {
    kerf::test::writeFile(work / name, "G90 G21\nG92 X0 Y-15 U0 V-15\nG01 X0 Y-10 U" +
                                           std::string(contour == turned ? "0.1571 V-8.9986" : "0 V-9") + "\n" +
                                           contour + "G01 X0 Y-15 U0 V-15\nM02\n");
    return json::parse(run("'" + std::string(KERF_PROGRAM) + "' check --json '" + (work / name).string() +
                               "' --drawing '" + (work / "taper.dxf").string() +
                               "' --thickness 20 --drawing-layer LOWER --drawing-upper-layer UPPER 2>/dev/null",
                           work / (name + ".json"), exit));
  };
  const json straight = check("taper_straight.nc", square + "G01 X0 Y-10 U0 V-9\n");
  EXPECT_EQ(exit, 0) << straight["diagnostics"].dump(1);
  EXPECT_EQ(straight["summary"]["comparison"]["out_of_tolerance"], 0);
  EXPECT_EQ(straight["summary"]["comparison_upper"]["out_of_tolerance"], 0);
  const json r = check("taper_turned.nc", turned);
  EXPECT_EQ(exit, 1);
  EXPECT_EQ(r["summary"]["comparison"]["out_of_tolerance"], 0) << "the lower plane is as drawn";
  EXPECT_EQ(r["summary"]["comparison_upper"]["out_of_tolerance"], r["summary"]["comparison_upper"]["elements"].size());
  const auto named = findings(r, "K0634");
  ASSERT_EQ(named.size(), 1u) << r["diagnostics"].dump(1);
  EXPECT_TRUE(says(named[0], "turned 1.0000°") || says(named[0], "turned 0.9999°")) << named[0].dump();
  // A drawn corner (9, -9) against the turned sides: 9 (sin 1° + cos 1° - 1) = 155.7 µm from the nearer.
  double worst = 0;
  for (const json& e : r["summary"]["comparison_upper"]["elements"])
    worst = std::max(worst, e["deviation_mm"].get<double>());
  const double degree = std::acos(-1.0) / 180;
  EXPECT_NEAR(worst, 9 * (std::sin(degree) + std::cos(degree) - 1), 1e-4);
}

class DxfAgainstEzdxf : public testing::Test {
 public:
  explicit DxfAgainstEzdxf(fs::path file) : file_(std::move(file)) {}

  void TestBody() override {
    const fs::path work = fs::path(KERF_DXF_WORK);
    fs::create_directories(work);
    const std::string name = file_.filename().string();
    int exit = 0;
    const std::string oracleText =
        run("'" + std::string(KERF_PYTHON) + "' '" + std::string(KERF_DXF_ORACLE) + "' '" + file_.string() + "' 0.001",
            work / (name + ".ezdxf.json"), exit);
    ASSERT_EQ(exit, 0) << "the ezdxf oracle failed on " << file_ << " (python3-ezdxf, python3-shapely: "
                       << ".ci/install-deps.sh --tests)";
    const std::string kerfText =
        run("'" + std::string(KERF_PROGRAM) + "' check --json '" + file_.string() + "' 2>/dev/null",
            work / (name + ".kerf.json"), exit);
    ASSERT_LT(exit, 2) << file_;
    const json oracle = json::parse(oracleText);
    const json report = json::parse(kerfText);
    ASSERT_TRUE(report.contains("drawing")) << kerfText.substr(0, 500);
    const json& d = report["drawing"];
    EXPECT_EQ(report["summary"]["format"], "dxf");

    // Entity counts by type.
    EXPECT_EQ(d["entities"], oracle["entities"]) << file_;

    // Length of everything that can be a contour.
    double length = 0.0;
    std::vector<double> areas;
    std::size_t closed = 0, branched = 0;
    for (const json& c : d["contours"]) {
      length += c["length"].get<double>();
      if (c["closed"].get<bool>()) {
        ++closed;
        areas.push_back(c["area"].get<double>());
      }
    }
    const double want = oracle["length"].get<double>();
    // The oracle's flattening may shorten curves by its stated slack, never lengthen them.
    EXPECT_NEAR(length, want, 1e-7 * want + oracle["length_slack"].get<double>() + 1e-6) << file_;

    // Chaining, where the graph of ends does not branch.
    if (oracle["branch_nodes"].get<int>() == 0) {
      EXPECT_EQ(d["contours"].size(), oracle["components"].get<std::size_t>()) << file_;
      EXPECT_EQ(closed, oracle["loops"].get<std::size_t>()) << file_;
      const std::vector<double> theirs = oracle["loop_areas"].get<std::vector<double>>();
      const std::vector<double> slack = oracle["loop_area_slack"].get<std::vector<double>>();
      std::sort(areas.begin(), areas.end());
      ASSERT_EQ(areas.size(), theirs.size());
      for (std::size_t i = 0; i < areas.size(); ++i)
        EXPECT_NEAR(areas[i], theirs[i], 1e-7 * theirs[i] + slack[i] + 1e-9) << i;
    } else {
      ++branched;
    }
    std::printf("%s: %zu contours (%zu closed), length %.4f mm (ezdxf %.4f)%s\n", name.c_str(), d["contours"].size(),
                closed, length, want, branched ? "; ends branch: chaining compared by length only" : "");
  }

 private:
  fs::path file_;
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const fs::path dir = fs::path(KERF_REALWORLD_DIR) / "dxf";
  if (fs::is_directory(dir))  // the corpus lives beside the project
    for (const fs::path& f : kerf::test::sortedEntries(dir, false, ".dxf")) {
      std::string name = f.stem().string();
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      testing::RegisterTest("dxf_ezdxf_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [f]() -> testing::Test* { return new DxfAgainstEzdxf(f); });
    }
  return RUN_ALL_TESTS();
}
