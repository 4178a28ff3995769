// Timed harness for 4-axis taper programs: read, build the surface measures, run every check,
// mesh the surface. Prints figures; asserts only that the generated part reads and checks
// clean (so the CTest smoke run fails if the harness rots). No speed target is checked here.
//
//   kerf_bench_taper [--moves N] [--repeat R] [--dialect xyuv-abs|taper-angle]
//
// The part: N moves around a circle of radius 5 m, alternating lines and R arcs that bulge out.
// xyuv-abs: the upper contour is the lower one scaled by 0.999 about the centre (5 mm in, over
// 50 mm: 5.7 degrees), arcs with their own R. taper-angle: the same lower contour under G51 A3.
#include "kerf/converter/check/checks.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/interpret/analysis.h"
#include "kerf/geometry/ruled_surface.h"

#include "bench_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using kerf::bench::Clock;
using kerf::bench::peakRssKiB;
using kerf::bench::seconds;

std::string generate(std::size_t moves, bool taperAngle) {
  std::string text;
  text.reserve(moves * 64);
  const double radius = 5000.0, scale = 0.999;
  const double arcRadius = 0.6 * 2 * M_PI * radius / static_cast<double>(moves);
  char line[192];
  if (taperAngle) {
    text += "%\nG21 G90\nG92 X5000. Y-5. I50.\nG51 A3.\nG01 X5000. Y0 F2.\n";
  } else {
    text += "%\nM101 P50.\nG21 G90\nG92 X5000. Y0 U4995. V0\nF2.\n";
  }
  for (std::size_t i = 1; i <= moves; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(moves);
    const double x = i == moves ? radius : radius * std::cos(a);
    const double y = i == moves ? 0.0 : radius * std::sin(a);
    const bool arc = i % 2 == 0;
    if (taperAngle) {
      if (arc)
        std::snprintf(line, sizeof line, "G02 X%.4f Y%.4f R%.4f\n", x, y, arcRadius);
      else
        std::snprintf(line, sizeof line, "G01 X%.4f Y%.4f\n", x, y);
    } else if (arc) {
      std::snprintf(line, sizeof line, "G02 X%.4f Y%.4f R%.4f U%.4f V%.4f R%.4f\n", x, y, arcRadius, scale * x,
                    scale * y, scale * arcRadius);
    } else {
      std::snprintf(line, sizeof line, "G01 X%.4f Y%.4f U%.4f V%.4f\n", x, y, scale * x, scale * y);
    }
    text += line;
  }
  text += taperAngle ? "G50\nG01 X5000. Y-5.\nM02\n%\n" : "M02\n%\n";
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t moves = 100'000;
  int repeat = 3;
  bool taperAngle = false;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--moves"))
      moves = std::strtoul(argv[i + 1], nullptr, 10);
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--dialect"))
      taperAngle = !std::strcmp(argv[i + 1], "taper-angle");
  }
  using namespace kerf::converter;
  const std::string text = generate(moves, taperAngle);
  std::printf("taper program (%s): %zu moves, %.1f MB\n", taperAngle ? "taper-angle" : "xyuv-abs", moves,
              static_cast<double>(text.size()) / 1e6);
  const long rssBefore = peakRssKiB();
  double bestRead = 1e30, bestMeasure = 1e30, bestCheck = 1e30, bestMesh = 1e30, bestTotal = 1e30;
  std::size_t triangles = 0;
  bool clean = true;
  for (int r = 0; r < repeat; ++r) {
    SourceFile src("bench.nc", text);
    Diagnostics diags(20);
    const auto t0 = Clock::now();
    const Analysis a = analyse(src, {}, diags);
    const auto t1 = Clock::now();
    const SurfaceMeasures m = measureSurface(a.toolpath);
    const auto t2 = Clock::now();
    checkToolpath(a.toolpath, &src, {}, diags, &m);
    const auto t3 = Clock::now();
    const CutPath path = cutPath(a.toolpath);
    std::vector<kerf::geometry::Segment> upper;
    for (std::size_t i : path.moveIndex) upper.push_back(a.toolpath.upper[i]);
    kerf::geometry::MeshOptions mo;
    mo.tolerance = 0.01;
    const kerf::geometry::Mesh mesh =
        kerf::geometry::meshRuledSurface(path.segments, upper, a.toolpath.heights.planes, mo);
    const auto t4 = Clock::now();
    bestRead = std::min(bestRead, seconds(t0, t1));
    bestMeasure = std::min(bestMeasure, seconds(t1, t2));
    bestCheck = std::min(bestCheck, seconds(t2, t3));
    bestMesh = std::min(bestMesh, seconds(t3, t4));
    bestTotal = std::min(bestTotal, seconds(t0, t3));
    triangles = mesh.triangles.size();
    if (diags.hasErrors() || !a.toolpath.isTaper() || a.toolpath.moves.size() < moves) {
      clean = false;
      for (const auto& d : diags.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
    }
  }
  std::printf("read (parse + interpret): %7.3f s\n", bestRead);
  std::printf("surface measures:         %7.3f s  (slope, U/V offsets, area per patch)\n", bestMeasure);
  std::printf("all checks:               %7.3f s  (contours on both planes, slope, twist, folds, 15 sections)\n",
              bestCheck);
  std::printf("read + surface + checks:  %7.3f s\n", bestTotal);
  std::printf("mesh at 0.01 mm:          %7.3f s  %zu triangles\n", bestMesh, triangles);
  std::printf("peak memory:              %7.1f MiB (before reading: %.1f MiB)\n",
              static_cast<double>(peakRssKiB()) / 1024.0, static_cast<double>(rssBefore) / 1024.0);
  if (!clean) {
    std::fprintf(stderr, "the benchmark part should read and check clean\n");
    return 1;
  }
  return 0;
}
