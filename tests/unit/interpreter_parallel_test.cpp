// Runs of simple blocks interpreted on every core (simple_runs.cpp) give the block loop's result
// bit for bit: every move, the centre words, the arc-centre tally and the diagnostics.
#include "converter_support.h"
#include "kerf/converter/machine.h"
#include "kerf/converter/report.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace kerf::converter;
using kerf::geometry::Segment;
using kerf::geometry::Vec2;

namespace {

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }  // NaN and -0 too
bool same(const Vec2& a, const Vec2& b) { return same(a.x(), b.x()) && same(a.y(), b.y()); }
bool same(const Segment& a, const Segment& b) {
  return a.kind == b.kind && same(a.start, b.start) && same(a.end, b.end) && same(a.centre, b.centre) &&
         same(a.radius, b.radius) && same(a.startAngle, b.startAngle) && same(a.sweep, b.sweep);
}

struct Outcome {
  Interpretation result;
  std::string diags;
};

Outcome interpretWith(const SourceFile& source, InterpreterOptions options, std::size_t run, std::size_t stretches,
                      std::size_t window = 1000) {
  options.parallelRun = run;
  options.parallelWindow = window;
  options.parallelStretches = stretches;
  Diagnostics diags(1000);
  const Program program = parseProgram(source, diags);
  Outcome o{interpretProgram(program, options, diags), {}};
  for (const Diagnostic& d : diags.all()) o.diags += formatDiagnostic(d);
  return o;
}

/// The block loop alone against windows of a few blocks cut into `stretches`.
/// Returns how many blocks went in windows.
std::size_t expectSameAsBlockLoop(const SourceFile& source, const InterpreterOptions& options, std::size_t stretches,
                                  std::size_t window = 1000) {
  const Outcome serial = interpretWith(source, options, 0, 0);
  const Outcome parallel = interpretWith(source, options, 4, stretches, window);
  const Toolpath& a = serial.result.toolpath;
  const Toolpath& b = parallel.result.toolpath;
  EXPECT_EQ(a.moves.size(), b.moves.size()) << source.name();
  if (a.moves.size() != b.moves.size()) return 0;
  for (std::size_t i = 0; i < a.moves.size(); ++i) {
    const Move& x = a.moves[i];
    const Move& y = b.moves[i];
    const bool equal = same(x.lower, y.lower) && x.kind == y.kind && x.centreForm == y.centreForm &&
                       x.wireOffset == y.wireOffset && x.callDepth == y.callDepth && x.line == y.line &&
                       x.span.offset == y.span.offset && x.span.length == y.span.length && x.feedIndex == y.feedIndex;
    EXPECT_TRUE(equal) << source.name() << " move " << i << " (line " << x.line << "), " << stretches << " stretches";
    if (!equal) return 0;
  }
  EXPECT_EQ(a.centreWords.size(), b.centreWords.size());
  for (std::size_t i = 0; i < std::min(a.centreWords.size(), b.centreWords.size()); ++i)
    EXPECT_TRUE(same(a.centreWords[i], b.centreWords[i])) << source.name() << " centre words " << i;
  EXPECT_EQ(a.feeds, b.feeds);
  EXPECT_TRUE(same(a.start, b.start));
  EXPECT_EQ(serial.result.arcs.arcs, parallel.result.arcs.arcs);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(serial.result.arcs.closes[k], parallel.result.arcs.closes[k]);
  EXPECT_EQ(serial.result.arcs.firstFailLine, parallel.result.arcs.firstFailLine);
  EXPECT_EQ(serial.diags, parallel.diags) << source.name();
  EXPECT_EQ(serial.result.blocksInWindows, 0u);
  return parallel.result.blocksInWindows;
}

/// Lines and arcs (R and I J), axes left out, the motion and the feed alone, rapids, a G92 shift,
/// an incremental stretch and a wire offset: every case a window meets.
std::string mixedProgram(std::size_t blocks) {
  std::ostringstream p;
  p << "G21 G90 G17\nG92 X3. Y-2.\nF2.5\nG01 X0 Y0\n";
  double x = 0.0;
  for (std::size_t i = 0; i < blocks; ++i) {
    switch (i % 9) {
      case 0: p << "G01 X" << x + 1.0 << " Y0.5\n"; break;
      case 1: p << "Y0.25\n"; break;
      case 2: p << "G02 X" << x + 2.0 << " Y0.5 R0.7\n"; break;
      case 3: p << "G03 X" << x + 2.5 << " Y0.5 I0.25 J0.25\n"; break;
      case 4: p << "F2.5\n"; break;
      case 5: p << "G01\n"; break;
      case 6: p << "X" << x + 3.0 << "\n"; break;
      case 7: p << "G00 X" << x + 3.0 << " Y0\n"; break;
      default: p << "G01 X" << x + 3.5 << " Y0 F2.5\n"; break;
    }
    if (i % 9 == 8) x += 3.5;
    if (i == blocks / 3) p << "G92 X" << x - 7.0 << " Y1.\n";  // a shift: program = toolpath + shift
    if (i == blocks / 2) p << "G91\nG01 X0.5 Y0.25\nY-0.25\nX-0.5\nG90\n";
    if (i == 2 * blocks / 3) p << "G41 D1\n";
  }
  p << "G40 G01 X" << x << " Y-1.\nM02\n";
  return p.str();
}

TEST(interpreter_parallel, mixed_runs_match_the_block_loop) {
  const SourceFile source("mixed.nc", mixedProgram(400));
  InterpreterOptions options;
  options.wireOffset = 0.1;
  for (std::size_t stretches : {1u, 2u, 3u, 7u}) EXPECT_GT(expectSameAsBlockLoop(source, options, stretches), 300u);
  options.recordCentreWords = false;
  EXPECT_GT(expectSameAsBlockLoop(source, options, 3), 300u);
}

TEST(interpreter_parallel, windows_do_run_on_a_long_program) {
  // A sanity check that the comparison above is not between two block loops: a run this long
  // goes in windows, and its moves then are the same too.
  const SourceFile source("long.nc", mixedProgram(40000));
  InterpreterOptions options;
  options.wireOffset = 0.1;
  const Outcome serial = interpretWith(source, options, 0, 0);
  EXPECT_EQ(serial.diags.find("error"), std::string::npos) << serial.diags;
  EXPECT_GT(serial.result.toolpath.moves.size(), 30000u);
  EXPECT_GT(expectSameAsBlockLoop(source, options, 2), 30000u);
}

TEST(interpreter_parallel, a_stretch_takes_the_position_and_motion_from_the_blocks_before_it) {
  // The motion code further back than the last X and Y, a shift, and stretch starts at every
  // phase of the pattern: a stretch that started from the run's state would make rapids of lines.
  std::ostringstream p;
  p << "G90 G01 X0 Y0\nG92 X2. Y3.\n";
  for (int i = 0; i < 20; ++i)
    p << "G01 X" << 3 * i + 1 << " Y" << i % 3 << "\nX" << 3 * i + 2 << "\nY" << i % 3 + 1 << "\nG00\nX" << 3 * i + 3
      << "\nY" << i % 2 << ".5\n";
  p << "M02\n";
  const SourceFile source("phases.nc", p.str());
  for (std::size_t stretches = 1; stretches <= 13; ++stretches)
    EXPECT_GT(expectSameAsBlockLoop(source, {}, stretches), 100u) << stretches << " stretches";
  const SourceFile relative("relative.nc", "G91 G01 X1. Y1.\n" + p.str().substr(p.str().find("G01 X1")));
  for (std::size_t stretches = 2; stretches <= 5; ++stretches)
    EXPECT_GT(expectSameAsBlockLoop(relative, {}, stretches), 100u) << stretches << " stretches";
}

TEST(interpreter_parallel, what_a_window_would_not_say_the_block_loop_says) {
  // An arc that does not close, a zero-length line, I J on a line, a new feed and an arc with
  // both R and I J inside long runs: each window that meets one is given back.
  std::ostringstream p;
  p << "G90 G01 X0 Y0\n";
  for (int i = 0; i < 60; ++i) {
    p << "G01 X" << i + 0.5 << " Y0\n";
    if (i == 10) p << "G02 X" << i + 5.0 << " Y0 R0.1\n";  // radius too small
    if (i == 20) p << "X" << i + 0.5 << "\n";              // zero length
    if (i == 30) p << "G01 X" << i + 0.6 << " I1.\n";      // I on a line
    if (i == 40) p << "F3.\n";                             // a new feed
    if (i == 50) p << "G03 X" << i + 0.5 << " Y1. R0.5 I0.5\n";
    p << "G01 X" << i + 1.0 << " Y0\n";
  }
  p << "M02\n";
  const SourceFile source("says.nc", p.str());
  // Windows of 8 blocks: those without such a block run, the others are given back.
  for (std::size_t stretches : {1u, 2u, 3u}) {
    const std::size_t inWindows = expectSameAsBlockLoop(source, {}, stretches, 8);
    EXPECT_GT(inWindows, 20u);
    EXPECT_LT(inWindows, 100u);
  }
}

TEST(interpreter_parallel, real_programs_match_the_block_loop) {
  std::size_t programs = 0;
  for (const char* folder : {"iso2d", "polar", "xyuv"}) {
    const std::filesystem::path dir = std::filesystem::path(KERF_REALWORLD_DIR) / folder;
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      const SourceFile source(entry.path().filename().string(), text.str());
      for (const char* machine : {"generic", "robofil", "sodick", "linuxcnc", "cnc3", "ncvc", "fanuc"}) {
        InterpreterOptions options;
        options.machine = findBuiltinMachine(machine);
        ASSERT_NE(options.machine, nullptr) << machine;
        for (std::size_t stretches : {2u, 3u}) expectSameAsBlockLoop(source, options, stretches);
      }
      ++programs;
    }
  }
  EXPECT_GE(programs, 10u) << "the real programs are at " << KERF_REALWORLD_DIR;
}

}  // namespace
