// Timed harness for the reading pipeline and the 2-axis checks. Prints figures; asserts only
// that the generated program reads without errors and without self-intersections (so a smoke
// run in CTest fails if the harness rots). Speed targets are never checked here: machines are
// shared and noisy; the figures go to the README.
//
//   kerf_bench [--blocks N] [--repeat R] [--shape circle|star|spiral|crossing] [--sweeps all|auto] [--write FILE]
//   (--sweeps auto: only the method kerf check runs, not the box and decision sweeps alone)
//
// --write FILE writes the program and stops (tests/bench/compare.sh times kerf check and LinuxCNC's
// rs274 on it).
//
// The program: a closed contour of N moves around a circle of radius 5 m, alternating G01 lines
// and G02 R arcs that bulge out, 4 decimals, absolute coordinates. --shape star: N G01 lines
// between radii 100 and 40 mm, a star of long spikes whose boxes nearly all overlap (the
// adversarial shape for a sweep over boxes, issue 13). --shape spiral: N modal `X Y` lines at 3
// decimals, 1,000 a turn, on a spiral of radius 5000 mm growing 0.05 mm a turn, which never meets
// itself (issue 13's 200 MB program is --blocks 10000000 --write: the turns' boxes pile up, so the
// check takes the decision sweep). --shape crossing: a tangled walk, random where the others are
// regular (issue 58): N moves wandering in random steps over a field 800 mm across, lines and arcs
// in every form (R of both signs, I J arcs swept up to nearly a full turn), one step in fifty a long
// one across the tangle, G90 and G91 switching every 300 blocks. It crosses itself many thousands
// of times: the check must report them (up to its limit), not only find one.
#include "kerf/converter/check/checks.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/interpret/analysis.h"
#include "kerf/geometry/intersection.h"
#include "kerf/geometry/parallel.h"
#include "kerf/geometry/tessellation.h"

#include "bench_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

using kerf::bench::Clock;
using kerf::bench::peakRssKiB;
using kerf::bench::seconds;

std::string generateStar(std::size_t blocks) {
  std::string text;
  text.reserve(blocks * 30);
  text += "%\nO9001 (kerf benchmark star)\nG21 G90 G17\nG92 X100. Y0\n";
  char line[96];
  for (std::size_t i = 1; i <= blocks; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(blocks);
    const double r = i % 2 ? 40.0 : 100.0;
    const double x = i == blocks ? 100.0 : r * std::cos(a), y = i == blocks ? 0.0 : r * std::sin(a);
    std::snprintf(line, sizeof line, "G01 X%.4f Y%.4f\n", x, y);
    text += line;
  }
  text += "M02\n%\n";
  return text;
}

std::string generate(std::size_t blocks) {
  std::string text;
  text.reserve(blocks * 36);
  text += "%\nO9000 (kerf benchmark)\nG21 G90 G17\nG92 X5000. Y0\nF2.\n";
  const double radius = 5000.0;
  // Arcs of radius 0.6 x the chord: they bulge 0.27 chord out, far from their neighbours.
  const double arcRadius = 0.6 * 2 * M_PI * radius / static_cast<double>(blocks);
  char line[128];
  for (std::size_t i = 1; i <= blocks; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(blocks);
    const double x = i == blocks ? radius : radius * std::cos(a);
    const double y = i == blocks ? 0.0 : radius * std::sin(a);
    if (i % 2) {
      std::snprintf(line, sizeof line, "G01 X%.4f Y%.4f\n", x, y);
    } else {
      // Counter-clockwise travel around the circle; G02 bulges outward (to the right).
      std::snprintf(line, sizeof line, "G02 X%.4f Y%.4f R%.4f\n", x, y, arcRadius);
    }
    text += line;
  }
  text += "M02\n%\n";
  return text;
}

std::string generateSpiral(std::size_t blocks) {
  std::string text;
  text.reserve(blocks * 21 + 64);
  text += "%\nO9002 (kerf benchmark spiral)\nG21 G90 G17\nG92 X5000. Y0\nF2.\nG01";
  char line[96];
  for (std::size_t i = 1; i <= blocks; ++i) {
    const double turns = static_cast<double>(i) / 1000.0;
    const double r = 5000.0 + 0.05 * turns, a = 2 * M_PI * turns;
    std::snprintf(line, sizeof line, " X%.3f Y%.3f\n", r * std::cos(a), r * std::sin(a));
    text += i == 1 ? line : line + 1;
  }
  text += "M02\n%\n";
  return text;
}

/// A number at 4 decimals, as an integer count of 0.1 µm: the generators write exact decimals, and
/// the incremental words are differences of those, so G91 stretches never drift.
long long tenths(double mm) { return std::llround(mm * 10000.0); }
std::string decimal(long long t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%s%lld.%04lld", t < 0 ? "-" : "", std::llabs(t) / 10000, std::llabs(t) % 10000);
  return buf;
}

std::string generateCrossing(std::size_t blocks) {
  std::string text;
  text.reserve(blocks * 40);
  text += "%\nO9003 (kerf benchmark crossing)\nG21 G90 G17\nG92 X0 Y0\nF2.\n";
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto uniform = [&] {  // [0, 1), a fixed sequence on every machine
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  constexpr double kField = 400.0;  // the walk turns back at this distance from the origin, mm
  long long x = 0, y = 0;
  bool incremental = false;
  double heading = 0.0;
  auto moveTo = [&](const char* code, long long nx, long long ny, const std::string& more) {
    text += code;
    text += " X" + decimal(incremental ? nx - x : nx) + " Y" + decimal(incremental ? ny - y : ny) + more + "\n";
    x = nx;
    y = ny;
  };
  for (std::size_t i = 1; i <= blocks; ++i) {
    if (i % 300 == 0) {  // the distance mode changes every 300 blocks
      incremental = !incremental;
      text += incremental ? "G91\n" : "G90\n";
    }
    // The heading wanders; past the field's edge it turns back towards the middle.
    const double px = static_cast<double>(x) / 10000.0, py = static_cast<double>(y) / 10000.0;
    heading += 0.8 * (uniform() - 0.5);
    if (std::hypot(px, py) > kField) heading = std::atan2(-py, -px) + 0.6 * (uniform() - 0.5);
    // Mostly short steps; one in 50 a long one across the tangle.
    const double step = uniform() < 0.02 ? 20.0 + 60.0 * uniform() : 0.3 + 3.0 * uniform();
    const long long nx = tenths(px + step * std::cos(heading)), ny = tenths(py + step * std::sin(heading));
    const double chord = std::hypot(static_cast<double>(nx - x), static_cast<double>(ny - y)) / 10000.0;
    const double pick = uniform();
    if (pick < 0.4 || chord < 0.05) {
      moveTo("G01", nx, ny, "");
    } else if (pick < 0.65) {  // R, the short way
      moveTo(uniform() < 0.5 ? "G03" : "G02", nx, ny, " R" + decimal(tenths(chord * (0.6 + 2 * uniform()))));
    } else if (pick < 0.8) {  // R negative: the long way round a circle a little wider than the chord
      moveTo(uniform() < 0.5 ? "G03" : "G02", nx, ny, " R" + decimal(-tenths(chord * (0.52 + 0.5 * uniform()))));
    } else {  // I J: a circle through the start, swept up to nearly all the way round
      const double radius = chord * (0.3 + uniform()), toCentre = heading + M_PI / 2;
      const long long cx = x + tenths(radius * std::cos(toCentre)), cy = y + tenths(radius * std::sin(toCentre));
      const double r = std::hypot(static_cast<double>(x - cx), static_cast<double>(y - cy));
      const double to = std::atan2(static_cast<double>(y - cy), static_cast<double>(x - cx)) + 0.2 + 6.0 * uniform();
      moveTo("G03", cx + std::llround(r * std::cos(to)), cy + std::llround(r * std::sin(to)),
             " I" + decimal(cx - x) + " J" + decimal(cy - y));
      heading = to + M_PI / 2;
    }
  }
  text += "G90\nM02\n%\n";
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t blocks = 1'000'000;
  int repeat = 3;
  bool star = false, spiral = false, crossing = false, autoOnly = false;
  const char* write = nullptr;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--sweeps")) autoOnly = !std::strcmp(argv[i + 1], "auto");
    if (!std::strcmp(argv[i], "--shape")) {
      star = !std::strcmp(argv[i + 1], "star");
      spiral = !std::strcmp(argv[i + 1], "spiral");
      crossing = !std::strcmp(argv[i + 1], "crossing");
    } else if (!std::strcmp(argv[i], "--blocks"))
      blocks = std::strtoul(argv[i + 1], nullptr, 10);
    else if (!std::strcmp(argv[i], "--write"))
      write = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::max(1, std::atoi(argv[i + 1]));
  }
  using namespace kerf::converter;
  if (star && blocks % 2) ++blocks;  // the spikes alternate: an even count closes the star
  // The library works on as many threads as the program says (kerf sets the hardware's count).
  kerf::geometry::setWorkerCount(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
  const std::string text = star       ? generateStar(blocks)
                           : spiral   ? generateSpiral(blocks)
                           : crossing ? generateCrossing(blocks)
                                      : generate(blocks);
  const double mb = static_cast<double>(text.size()) / 1e6;
  if (write) {
    std::FILE* out = std::fopen(write, "wb");
    const bool ok = out && std::fwrite(text.data(), 1, text.size(), out) == text.size();
    if (out && std::fclose(out) != 0) return 1;
    if (!ok) {
      std::fprintf(stderr, "cannot write %s\n", write);
      return 1;
    }
    std::printf("wrote %zu blocks, %.1f MB to %s\n", blocks, mb, write);
    return 0;
  }
  std::printf("program: %zu blocks, %.1f MB\n", blocks, mb);
  const long rssBefore = peakRssKiB();

  double bestParse = 1e30, bestInterp = 1e30;
  Analysis analysis;
  for (int r = 0; r < repeat; ++r) {
    SourceFile src("bench.nc", text);
    Diagnostics diags(20);
    const auto t0 = Clock::now();
    Program program = parseProgram(src, diags);
    const auto t1 = Clock::now();
    Toolpath toolpath = interpret(program, {}, diags);
    const auto t2 = Clock::now();
    bestParse = std::min(bestParse, seconds(t0, t1));
    bestInterp = std::min(bestInterp, seconds(t0, t2));
    if (diags.hasErrors()) {
      std::fprintf(stderr, "benchmark program has errors:\n%s\n", formatDiagnostic(diags.all().front()).c_str());
      return 1;
    }
    if (r == repeat - 1) analysis = Analysis{std::move(program), std::move(toolpath)};
  }
  std::printf("parse:              %8.3f s  %8.1f MB/s  %10.0f blocks/s\n", bestParse, mb / bestParse,
              static_cast<double>(blocks) / bestParse);
  std::printf("parse + interpret:  %8.3f s  %8.1f MB/s  %10.0f blocks/s\n", bestInterp, mb / bestInterp,
              static_cast<double>(blocks) / bestInterp);

  const CutPath path = cutPath(analysis.toolpath);
  double bestSample = 1e30;
  std::size_t points = 0;
  for (int r = 0; r < repeat; ++r) {
    std::vector<kerf::geometry::Vec2> pts;
    const auto t0 = Clock::now();
    const auto stats = kerf::geometry::samplePath(path.segments, kerf::geometry::Sampling::step(0.01), &pts);
    const auto t1 = Clock::now();
    bestSample = std::min(bestSample, seconds(t0, t1));
    points = stats.points;
  }
  std::printf("tessellation k=0.01: %7.3f s  %10zu points  %10.0f points/s\n", bestSample, points,
              static_cast<double>(points) / bestSample);

  // What kerf check runs (auto), the box sweep alone and the decision sweep alone, interleaved.
  using kerf::geometry::SweepMethod;
  const SweepMethod methods[] = {SweepMethod::Auto, SweepMethod::Boxes, SweepMethod::Decision};
  double best[3] = {1e30, 1e30, 1e30};
  std::size_t pairs[3] = {0, 0, 0}, found[3] = {0, 0, 0}, contacts = 0;
  for (int r = 0; r < repeat; ++r) {
    for (int m = 0; m < 3; ++m) {
      // The box sweep alone is quadratic on the star: 20 s at 1e5 spikes, half an hour at 1e6.
      if ((star || spiral || crossing) && m == 1 && blocks > 200'000) continue;
      if (autoOnly && m > 0) continue;
      kerf::geometry::SelfIntersectionOptions o;
      o.closed = true;
      o.method = methods[m];
      const auto t0 = Clock::now();
      const auto result = kerf::geometry::findSelfIntersections(path.segments, o);
      const auto t1 = Clock::now();
      best[m] = std::min(best[m], seconds(t0, t1));
      pairs[m] = result.candidatePairs;
      found[m] = result.contacts.size();
      if (m == 0) contacts = result.contacts.size();
    }
  }
  std::printf("self-intersection:  %11.6f s  %zu segments, %zu pairs tested, %zu contacts (auto)\n", best[0],
              path.segments.size(), pairs[0], contacts);
  if (best[1] < 1e30)
    std::printf("  boxes alone:      %8.3f s  %zu pairs\n", best[1], pairs[1]);
  else
    std::printf("  boxes alone:      not run (%s)\n", autoOnly ? "--sweeps auto" : "quadratic on this shape");
  if (best[2] < 1e30)
    std::printf("  decision alone:   %8.3f s  %zu pairs\n", best[2], pairs[2]);
  else
    std::printf("  decision alone:   not run (--sweeps auto)\n");

  Diagnostics checkDiags(20);
  const auto c0 = Clock::now();
  checkToolpath(analysis.toolpath, nullptr, {}, checkDiags);
  const auto c1 = Clock::now();
  std::printf("all 2-axis checks:  %8.3f s\n", seconds(c0, c1));
  std::printf("peak memory:        %8.1f MiB (before reading: %.1f MiB)\n", static_cast<double>(peakRssKiB()) / 1024.0,
              static_cast<double>(rssBefore) / 1024.0);
  if (found[2] != contacts || (best[1] < 1e30 && found[1] != contacts)) {
    std::fprintf(stderr, "the sweeps disagree: %zu contacts (auto), %zu (boxes), %zu (decision)\n", contacts, found[1],
                 found[2]);
    return 1;
  }
  if (crossing ? contacts < 6 * 5 * 2 : contacts != 0 || checkDiags.hasErrors()) {
    std::fprintf(stderr, crossing ? "the crossing program should cross itself\n"
                                  : "the benchmark contour should not meet itself\n");
    return 1;
  }
  return 0;
}
