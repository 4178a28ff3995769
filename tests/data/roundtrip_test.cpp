// Round trips through the kerf program: every emitter whose format Kerf reads (iso, 3b) writes every
// sample, every real program in ../shared/realworld and the 3B test vectors; reading the output
// back gives the same path within the format's resolution (ISO: 3 decimals, 3B: 1 µm).
//   reference: kerf check F --trace      output: kerf convert F --to E --force -o OUT
//   back:      kerf check OUT --trace    compare every move's ends (and arc centres, upper sides)
#include "data_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <regex>

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

struct KerfRun {
  int exit = -1;
  std::string out, err;
};

/// Runs kerf; `tag` names its stdout and stderr files (the cases run in parallel).
KerfRun kerf(const std::string& args, const std::string& tag) {
  const fs::path out = fs::path(KERF_ROUNDTRIP_WORK) / (tag + ".stdout");
  const fs::path err = fs::path(KERF_ROUNDTRIP_WORK) / (tag + ".stderr");
  fs::create_directories(out.parent_path());
  const std::string command =
      "'" + std::string(KERF_PROGRAM) + "' " + args + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  return KerfRun{WIFEXITED(status) ? WEXITSTATUS(status) : -1, kerf::test::readFile(out), kerf::test::readFile(err)};
}

double dist(double ax, double ay, double bx, double by) { return std::hypot(ax - bx, ay - by); }

struct Seg {
  std::string kind;  // line, rapid, arc
  double sx = 0, sy = 0, ex = 0, ey = 0, cx = 0, cy = 0;
  bool upper = false;
};

/// The moves of a trace (and their upper sides), in order.
std::vector<Seg> movesOf(const std::string& trace) {
  static const std::regex move(
      R"(^(\d+ |  upper )(line|rapid|arc cw|arc ccw) (\S+) (\S+) -> (\S+) (\S+)(?: centre (\S+) (\S+))?.*$)");
  std::vector<Seg> out;
  for (const std::string& line : kerf::test::splitLines(trace)) {
    std::smatch m;
    if (!std::regex_match(line, m, move)) continue;
    Seg s;
    s.upper = m[1].str()[0] == ' ';
    s.kind = m[2].str();
    s.sx = std::stod(m[3]);
    s.sy = std::stod(m[4]);
    s.ex = std::stod(m[5]);
    s.ey = std::stod(m[6]);
    if (m[7].matched) {
      s.cx = std::stod(m[7]);
      s.cy = std::stod(m[8]);
    }
    out.push_back(s);
  }
  return out;
}

/// Distance from p to a traced move (a line, or an arc from its start to its end about its centre).
double distanceToMove(const Seg& m, double px, double py) {
  const double ends = std::min(dist(px, py, m.sx, m.sy), dist(px, py, m.ex, m.ey));
  if (m.kind.rfind("arc", 0) == 0) {
    const double r = dist(m.sx, m.sy, m.cx, m.cy);
    const double a0 = std::atan2(m.sy - m.cy, m.sx - m.cx), a1 = std::atan2(m.ey - m.cy, m.ex - m.cx);
    const double a = std::atan2(py - m.cy, px - m.cx);
    const double twoPi = 2 * std::acos(-1.0);
    auto ccwFrom = [&](double from, double to) { return std::fmod(std::fmod(to - from, twoPi) + twoPi, twoPi); };
    const bool ccw = m.kind == "arc ccw";
    double sweep = ccw ? ccwFrom(a0, a1) : ccwFrom(a1, a0);
    if (sweep < 1e-12) sweep = twoPi;  // a full circle
    const bool inside = (ccw ? ccwFrom(a0, a) : ccwFrom(a, a0)) <= sweep;
    return inside ? std::abs(dist(px, py, m.cx, m.cy) - r) : ends;
  }
  const double dx = m.ex - m.sx, dy = m.ey - m.sy, len2 = dx * dx + dy * dy;
  if (len2 < 1e-24) return ends;
  const double t = std::clamp(((px - m.sx) * dx + (py - m.sy) * dy) / len2, 0.0, 1.0);
  return dist(px, py, m.sx + t * dx, m.sy + t * dy);
}

double distanceToPath(const std::vector<Seg>& path, double px, double py) {
  double best = 1e300;
  for (const Seg& m : path) best = std::min(best, distanceToMove(m, px, py));
  return best;
}

/// A point in the middle of a traced move.
std::pair<double, double> middleOf(const Seg& m) {
  if (m.kind.rfind("arc", 0) != 0) return {0.5 * (m.sx + m.ex), 0.5 * (m.sy + m.ey)};
  const double r = dist(m.sx, m.sy, m.cx, m.cy);
  const double a0 = std::atan2(m.sy - m.cy, m.sx - m.cx), a1 = std::atan2(m.ey - m.cy, m.ex - m.cx);
  const double twoPi = 2 * std::acos(-1.0);
  double sweep = std::fmod(std::fmod(a1 - a0, twoPi) + twoPi, twoPi);  // counter-clockwise
  if (sweep < 1e-12) sweep = twoPi;
  if (m.kind == "arc cw") sweep -= twoPi;
  const double a = a0 + 0.5 * sweep;
  return {m.cx + r * std::cos(a), m.cy + r * std::sin(a)};
}

struct Case {
  fs::path file;
  std::string to;
};

class RoundTrip : public testing::Test {
 public:
  explicit RoundTrip(Case c) : c_(std::move(c)) {}

  void TestBody() override {
    const std::string in = "'" + c_.file.string() + "'";
    const std::string tag = c_.file.filename().string() + "." + c_.to;
    const KerfRun ref = kerf("check --trace " + in, tag + ".ref");
    ASSERT_LT(ref.exit, 2) << c_.file;
    const bool taper = ref.out.find("\ndialect ") != std::string::npos;
    std::vector<Seg> want = movesOf(ref.out);
    const bool threeB = c_.to == "3b";
    if (threeB) {  // one plane (the lower); a move that does not move it has no 3B record
      want.erase(std::remove_if(want.begin(), want.end(),
                                [](const Seg& s) {
                                  return s.upper ||
                                         (s.kind.rfind("arc", 0) != 0 && dist(s.sx, s.sy, s.ex, s.ey) < 5e-4);
                                }),
                 want.end());
    }
    const fs::path out = fs::path(KERF_ROUNDTRIP_WORK) / (c_.file.filename().string() + "." + c_.to);
    fs::remove(out);
    const KerfRun conv = kerf("convert " + in + " --force --to " + c_.to + " -o '" + out.string() + "'" +
                                  (threeB && taper ? " --plane lower" : ""),
                              tag + ".convert");
    if (!fs::exists(out)) {  // nothing to write: the reference says why (no move at all)
      EXPECT_TRUE(want.empty()) << c_.file << ": convert wrote nothing (exit " << conv.exit << ")";
      return;
    }
    std::string backArgs = "check --trace '" + out.string() + "'";
    if (threeB && !want.empty()) {
      char start[96];
      std::snprintf(start, sizeof start, " --start %.6f,%.6f", want.front().sx, want.front().sy);
      backArgs += start;
    }
    const KerfRun back = kerf(backArgs, tag + ".back");
    ASSERT_LT(back.exit, 2) << out;
    std::vector<Seg> got = movesOf(back.out);
    ASSERT_EQ(got.size(), want.size()) << c_.file << " -> " << out << "\n" << back.out.substr(0, 2000);
    // ISO: 3 decimals (√2/2 · 0.001). 3B: the µm grid, and an arc whose source ends are off its
    // circle by more than the grid ends where its count does (docs/3b.md): 2.5 µm, not cumulative.
    const double tol = threeB ? 0.0025 : 0.0008;
    double worst = 0.0;
    for (std::size_t i = 0; i < want.size(); ++i) {
      const Seg &w = want[i], &g = got[i];
      SCOPED_TRACE(c_.file.string() + " move " + std::to_string(i));
      const bool arc = w.kind.rfind("arc", 0) == 0;
      if (threeB) {  // 3B has no rapid: a rapid comes back as a line
        EXPECT_EQ(arc, g.kind.rfind("arc", 0) == 0);
      } else {
        EXPECT_EQ(w.kind, g.kind);
      }
      EXPECT_EQ(w.upper, g.upper);
      const double d = std::max(dist(w.sx, w.sy, g.sx, g.sy), dist(w.ex, w.ey, g.ex, g.ey));
      worst = std::max(worst, d);
      EXPECT_LE(d, tol);
      if (arc && threeB) {  // the centre may move along the chord's bisector (docs/3b.md): the arc may not
        const auto [mx, my] = middleOf(g);
        EXPECT_LE(distanceToMove(w, mx, my), tol);
      } else if (arc) {
        EXPECT_LE(dist(w.cx, w.cy, g.cx, g.cy), 0.0012);
      }
    }
    std::printf("round trip %s --to %s: %zu moves, largest end deviation %.6f mm\n", c_.file.filename().c_str(),
                c_.to.c_str(), want.size(), worst);
  }

 private:
  Case c_;
};

// The polar X/C round trip: write --to polar (X a diameter, C in degrees, 4 decimals, the spiral
// between points within 0.001 mm of the element), read the X/C program back (its cutting moves
// drawn as the machine's spirals, geometry/polar.h) and compare as point sets: every end and
// middle of a move read back lies on the source's path, and every end and middle of a source
// cutting move lies on the path read back, within the tolerance plus the rounding of X and C at
// the part's largest radius.
class PolarRoundTrip : public testing::Test {
 public:
  explicit PolarRoundTrip(fs::path file) : file_(std::move(file)) {}

  /// A refused conversion is refused for a reason the source shows: a cutting move through the face
  /// centre, where C is undefined (K0805; the writer's centre gap is its 0.001 mm tolerance), or no
  /// move at all (K0813); with exit 1 and no file.
  void expectRefusalShownBySource(const KerfRun& conv, const std::vector<Seg>& want) const {
    EXPECT_EQ(conv.exit, 1) << file_ << ": " << conv.err;
    std::vector<Seg> cuts;
    for (const Seg& s : want)
      if (s.kind != "rapid") cuts.push_back(s);
    if (conv.err.find("[K0805]") != std::string::npos) {
      ASSERT_FALSE(cuts.empty()) << file_;
      EXPECT_LE(distanceToPath(cuts, 0.0, 0.0), 0.0011) << file_ << ": refused as through the centre, and no cut is";
    } else if (conv.err.find("[K0813]") != std::string::npos) {
      EXPECT_TRUE(want.empty()) << file_ << ": refused as having no move, and it has " << want.size();
    } else {
      ADD_FAILURE() << file_ << ": refused for none of the reasons a polar program can be: " << conv.err;
    }
  }

  void TestBody() override {
    const std::string in = "'" + file_.string() + "'";
    const std::string tag = file_.filename().string() + ".polar";
    const KerfRun ref = kerf("check --trace " + in, tag + ".ref");
    ASSERT_LT(ref.exit, 2) << file_;
    std::vector<Seg> want;
    for (const Seg& s : movesOf(ref.out))
      if (!s.upper) want.push_back(s);
    const fs::path out = fs::path(KERF_ROUNDTRIP_WORK) / tag;
    fs::remove(out);
    const KerfRun conv = kerf(
        "convert " + in + " --force --to polar --plane lower --decimals 4 -o '" + out.string() + "'", tag + ".convert");
    if (!fs::exists(out)) {
      expectRefusalShownBySource(conv, want);
      return;
    }
    const KerfRun back = kerf("check --trace '" + out.string() + "'", tag + ".back");
    ASSERT_LT(back.exit, 2) << out;
    const std::vector<Seg> got = movesOf(back.out);
    ASSERT_FALSE(got.empty()) << out;
    double reach = 0.0;
    for (const Seg& s : want) reach = std::max({reach, std::hypot(s.sx, s.sy), std::hypot(s.ex, s.ey)});
    // X rounds to half its last digit, in the program's unit (an inch program stays in inches).
    const double unit = kerf::test::readFile(out).find("G20") != std::string::npos ? 25.4 : 1.0;
    const double tol = 0.001 + 0.00005 * unit + reach * 0.00005 * std::acos(-1.0) / 180.0 + 1e-6;
    std::vector<Seg> wantCuts, gotCuts;
    for (const Seg& s : want)
      if (s.kind != "rapid") wantCuts.push_back(s);
    for (const Seg& s : got)
      if (s.kind != "rapid") gotCuts.push_back(s);
    double worstBack = 0.0, worstSource = 0.0;
    for (const Seg& g : gotCuts)
      for (const auto& [x, y] : {std::pair{g.sx, g.sy}, std::pair{g.ex, g.ey}, middleOf(g)})
        worstBack = std::max(worstBack, distanceToPath(want, x, y));
    for (const Seg& w : wantCuts)
      for (const auto& [x, y] : {std::pair{w.sx, w.sy}, std::pair{w.ex, w.ey}, middleOf(w)})
        worstSource = std::max(worstSource, distanceToPath(gotCuts, x, y));
    EXPECT_LE(worstBack, tol) << file_ << ": read back, off the source's path";
    EXPECT_LE(worstSource, tol) << file_ << ": the source's path, missed by what was read back";
    std::printf(
        "round trip %s --to polar: %zu cutting moves, %zu read back; largest distance %.6f mm (back to "
        "source) and %.6f mm (source to back), allowed %.6f\n",
        file_.filename().c_str(), wantCuts.size(), gotCuts.size(), worstBack, worstSource, tol);
  }

 private:
  fs::path file_;
};

// Seed 002 (Hadzhiyski et al., G-POST polar post): O30 mills a square on the face with a Y axis
// (X a diameter); O31 is the same path as X/C points. Transcribed from the paper's listings (the
// face moves N70-N100 of O30; O31's first points N70-N85 and its last, N1340).
TEST(seed002_test, o30_written_as_polar_starts_as_o31_and_ends_a_turn_further) {
  const fs::path in = fs::path(KERF_ROUNDTRIP_WORK) / "o30.nc";
  fs::create_directories(in.parent_path());
  kerf::test::writeFile(in,
                        "(seed 002 O30, N70-N100)\nG28 C0.\nG0 X-28. Y-29.\nG1 Y14. F120.\nX28.\nY-14.\nX-58.\nM30\n");
  const fs::path out = fs::path(KERF_ROUNDTRIP_WORK) / "o30.xc";
  fs::remove(out);
  // A milling path overruns its start (X-58.): for a wire that is a crossing, hence --force.
  kerf("convert '" + in.string() + "' --machine fanuc --force --to polar --tolerance 0.005 -o '" + out.string() + "'",
       "seed002");
  const auto lines = kerf::test::splitLines(kerf::test::readFile(out));
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines[1], "(seed 002 O30, N70-N100)");  // every line the writer does not convert, in place
  EXPECT_EQ(lines[2], "G28 C0.");
  EXPECT_EQ(lines[3], "G00 X64.404 C-115.769");        // O31 N70 (no move added before it)
  EXPECT_EQ(lines[4], "G01 X63.198 C-116.299 F120.");  // O31 N85, its feed as written
  const std::string& last = lines[lines.size() - 2];   // before M30
  EXPECT_EQ(last.substr(0, 8), "X64.404 ");            // O31 N1340: X64.404 C-154.231
  const double c = std::stod(last.substr(last.find('C') + 1));
  EXPECT_NEAR(c, -154.231 - 360.0, 1e-9) << "unwrapped: O31's C-154.231 one turn further";
}

// Seed 002's O66 is the same square in G12.1 mode (X a radius, C the virtual axis in mm), after
// `X240. C270.` turns the table (transcribed: N35-N115). Its post means the table's frame at C 0
// (--polar-frame table): the cut is O30's square exactly. Read as the Fanuc 15i-MA manual says
// (the default, tool), the frame turns with C270: the same square turned by 270 degrees.
TEST(seed002_test, o66_in_the_table_frame_is_o30s_square_and_the_tool_frame_turns_it) {
  const fs::path dir = fs::path(KERF_ROUNDTRIP_WORK);
  fs::create_directories(dir);
  const fs::path o30 = dir / "o30_square.nc", o66 = dir / "o66.nc";
  kerf::test::writeFile(o30,
                        "(seed 002 O30, N35-N100)\nG28 C0.\nG0 Z200.\nX-28. Y-29.\nZ5.\nZ-2.5\nG1 Y14. "
                        "F120.\nX28.\nY-14.\nX-58.\nM30\n");
  kerf::test::writeFile(o66,
                        "(seed 002 O66, N35-N115)\nN35 G28 C0.\nN60 G0 Z200.\nN65 X240. C270.\nN70 "
                        "G12.1\nN75 X-14. C-29.\nN80 Z5.\nN85 Z-2.5\nN90 G1 C14. F120.\nN95 X14.\nN100 "
                        "C-14.\nN105 X-29.\nN110 G13.1\nN115 X64.404 Z5.\nM30\n");
  auto cuts = [](const std::string& trace) {
    std::vector<Seg> out;
    for (const Seg& s : movesOf(trace))
      if (s.kind == "line" && dist(s.sx, s.sy, s.ex, s.ey) > 0.01) out.push_back(s);  // not N115's 0.5 um
    return out;
  };
  const KerfRun ref = kerf("check --machine fanuc --trace '" + o30.string() + "'", "o30_square");
  const KerfRun table = kerf("check --machine fanuc --polar-frame table --trace '" + o66.string() + "'", "o66_t");
  const KerfRun tool = kerf("check --machine fanuc --trace '" + o66.string() + "'", "o66_f");
  const std::vector<Seg> want = cuts(ref.out), got = cuts(table.out), turned = cuts(tool.out);
  ASSERT_EQ(want.size(), 4u) << ref.out;
  EXPECT_DOUBLE_EQ(want[0].sx, -14.0);  // O30's X is a diameter
  EXPECT_DOUBLE_EQ(want[0].sy, -29.0);
  ASSERT_EQ(got.size(), want.size()) << table.out;
  ASSERT_EQ(turned.size(), want.size()) << tool.out;
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("cut " + std::to_string(i));
    EXPECT_LE(dist(want[i].sx, want[i].sy, got[i].sx, got[i].sy), 1e-9);
    EXPECT_LE(dist(want[i].ex, want[i].ey, got[i].ex, got[i].ey), 1e-9);
    // Turned by 270 degrees: (x, y) -> (y, -x).
    EXPECT_LE(dist(want[i].sy, -want[i].sx, turned[i].sx, turned[i].sy), 1e-9);
    EXPECT_LE(dist(want[i].ey, -want[i].ex, turned[i].ex, turned[i].ey), 1e-9);
  }
  EXPECT_NE(table.out.find("K0238 polar interpolation starts with the table at C 270.000: read in the table's"),
            std::string::npos);
  EXPECT_NE(tool.out.find("K0238 polar interpolation starts with the table at C 270.000: its frame's x axis"),
            std::string::npos);
}

// A dwell on a lathe gives its time as X (`G4 X2.`): no move (the mill-turn reader).
/// The words of a line that the polar writer does not convert (X Y C I J R, G0-G3, G12.1/G13.1,
/// G90/G91), upper-cased, in order; comments as one word each.
std::vector<std::string> keptWords(const std::string& line) {
  std::vector<std::string> words;
  for (std::size_t i = 0; i < line.size();) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    if (line[i] == '(') {
      j = line.find(')', i) + 1;
    } else {
      while (j < line.size() && line[j] != ' ' && !std::isalpha(static_cast<unsigned char>(line[j])) && line[j] != '(')
        ++j;
    }
    const std::string w = line.substr(i, j - i);
    const char l = static_cast<char>(std::toupper(static_cast<unsigned char>(w[0])));
    const bool converted =
        std::strchr("XYCIJR", l) != nullptr ||
        (l == 'G' && (std::stod(w.substr(1)) <= 3 || w == "G12.1" || w == "G13.1" || w == "G90" || w == "G91"));
    if (!converted) words.push_back(w);
    i = j;
  }
  return words;
}

// Issue 42: a face program with its tool, spindle, Z plunges and retracts, feeds, comments and
// sequence numbers. `--to polar` converts the face words and keeps every other word in place —
// compared line by line with the source — and adds no move: the output's first move is the
// source's first, to X120 C0.
TEST(seed002_test, polar_output_keeps_every_word_it_does_not_convert_in_place) {
  const fs::path in = fs::path(KERF_ROUNDTRIP_WORK) / "face_slot.nc";
  fs::create_directories(in.parent_path());
  const std::string source =
      "%\nO1234 (FACE SLOT)\nN10 T0707\nN20 G97 S2000 M03\nN30 G0 X120. C0. Z5.\nN40 G12.1\nN50 G0 X20. "
      "C0.\nN60 G1 Z-2. F200.\nN70 G1 X20. C10. F120.\nN80 G3 X10. C20. R10.\nN90 G1 X-10. C20.\nN100 G0 Z5. "
      "(retract)\nN110 G13.1\nN120 G0 X120. C0.\nN130 M05\nN140 M30\n%\n";
  kerf::test::writeFile(in, source);
  const fs::path out = fs::path(KERF_ROUNDTRIP_WORK) / "face_slot.xc";
  fs::remove(out);
  kerf("convert '" + in.string() + "' --force --to polar -o '" + out.string() + "'", "face_slot");
  const auto got = kerf::test::splitLines(kerf::test::readFile(out));
  const auto want = kerf::test::splitLines(source);
  // Output lines that start a source line: those with the source's N word, or the source's line
  // itself; point lines after a block's first (X C alone) belong to that block.
  std::vector<std::string> starts;
  for (const std::string& l : got)
    if (!l.empty() && l[0] != 'X' && l.rfind("(written by Kerf", 0) != 0) starts.push_back(l);
  // N40 G12.1 and N110 G13.1 keep their N alone: explicit X/C needs no polar mode.
  const std::vector<std::string>& sourceLines = want;
  ASSERT_EQ(starts.size(), sourceLines.size()) << kerf::test::readFile(out);
  for (std::size_t k = 0; k < starts.size(); ++k)
    EXPECT_EQ(keptWords(starts[k]), keptWords(sourceLines[k])) << starts[k] << " | " << sourceLines[k];
  EXPECT_EQ(got[0], "%");  // the tape start stays first, the writer's comment after it
  EXPECT_EQ(starts[4].substr(0, 24), "N30 G00 X120.000 C0.000 ") << "the first move is the source's first";
  EXPECT_NE(kerf::test::readFile(out).find("N60 G1 Z-2. F200.\n"), std::string::npos) << "the plunge as written";
}

TEST(seed002_test, a_dwell_on_a_lathe_moves_nothing) {
  const fs::path in = fs::path(KERF_ROUNDTRIP_WORK) / "dwell.nc";
  fs::create_directories(in.parent_path());
  kerf::test::writeFile(in, "G28 C0.\nG0 X40. C0.\nG1 X20. F100\nG4 X2.\nG1 X20. C30.\nM30\n");
  const KerfRun r = kerf("check --trace '" + in.string() + "'", "dwell");
  const std::vector<Seg> moves = movesOf(r.out);
  ASSERT_EQ(moves.size(), 3u) << r.out;
  EXPECT_EQ(moves[2].kind, "arc ccw");  // X stays 20 (radius 10): the table turns 30 degrees
  EXPECT_NEAR(dist(moves[2].sx, moves[2].sy, 10.0, 0.0), 0.0, 1e-6);  // the trace has 6 decimals
  EXPECT_NEAR(dist(moves[2].ex, moves[2].ey, 10 * std::cos(std::acos(-1.0) / 6), 5.0), 0.0, 1e-6);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  std::vector<fs::path> files;
  for (const auto& f : kerf::test::sortedEntries(KERF_SAMPLES_DIR, false, ".nc")) files.push_back(f);
  for (const char* sub : {"iso2d", "xyuv"}) {
    if (!fs::is_directory(fs::path(KERF_REALWORLD_DIR) / sub)) continue;  // the corpus lives beside the project
    std::vector<fs::path> real;
    for (const auto& e : fs::directory_iterator(fs::path(KERF_REALWORLD_DIR) / sub))
      if (e.is_regular_file()) real.push_back(e.path());
    std::sort(real.begin(), real.end());
    files.insert(files.end(), real.begin(), real.end());
  }
  for (const char* f : {"3b/set_a.3b", "3b/set_b.3b", "3b/set_a.iso"})
    if (const fs::path p = fs::path(KERF_REALWORLD_DIR) / ".." / "testdata" / f; fs::exists(p)) files.push_back(p);
  for (const fs::path& f : files) {
    std::string name = f.filename().string() + "_polar";
    for (char& ch : name)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    testing::RegisterTest("roundtrip_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [f]() -> testing::Test* { return new PolarRoundTrip(f); });
  }
  for (const fs::path& f : files)
    for (const char* to : {"iso", "3b"}) {
      std::string name = f.filename().string() + "_" + to;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      testing::RegisterTest("roundtrip_test", name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [f, to]() -> testing::Test* {
                              return new RoundTrip(Case{f, to});
                            });
    }
  return RUN_ALL_TESTS();
}
