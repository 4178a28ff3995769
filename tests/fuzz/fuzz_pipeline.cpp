// Fuzz entry point for the pipeline every command takes (parser, machine detection, conventions
// from the evidence, interpreter, checks), the point emitters and the readers of the side files (a
// machine profile, an offset table) (libFuzzer ABI).
// Built as a real fuzzer with clang (-DKERF_BUILD_FUZZERS=ON, tests/fuzz/run.sh), and always
// as kerf_fuzz_replay, which feeds it every file of the bad corpus, the samples and
// tests/fuzz/corpus so CI replays what the fuzzer found.
// For a quarter of the inputs the pipeline runs on one worker and on three, and the two readings
// must be the same bit for bit, diagnostics included (the checks split their passes over threads).
#include "kerf/converter/check/summary.h"
#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/pipeline.h"
#include "kerf/converter/report/report.h"
#include "kerf/geometry/ruled_surface.h"

#include "../unit/test_support.h"
#include "kerf/converter/formats/emit.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The same diagnostics, as they are shown.
bool sameDiagnostics(const kerf::converter::Diagnostics& a, const kerf::converter::Diagnostics& b) {
  if (a.all().size() != b.all().size()) return false;
  for (std::size_t i = 0; i < a.all().size(); ++i)
    if (kerf::converter::formatDiagnostic(a.all()[i]) != kerf::converter::formatDiagnostic(b.all()[i])) return false;
  return true;
}

/// The same moves, bit for bit, and the same diagnostics.
bool sameReading(const kerf::converter::Pipeline& a, const kerf::converter::Pipeline& b) {
  const auto& x = a.toolpath.moves;
  const auto& y = b.toolpath.moves;
  if (x.size() != y.size() || a.diags.all().size() != b.diags.all().size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const kerf::geometry::Segment &s = x[i].lower, &t = y[i].lower;
    if (s.kind != t.kind || !sameBits(s.start.x(), t.start.x()) || !sameBits(s.start.y(), t.start.y()) ||
        !sameBits(s.end.x(), t.end.x()) || !sameBits(s.end.y(), t.end.y()) || !sameBits(s.centre.x(), t.centre.x()) ||
        !sameBits(s.centre.y(), t.centre.y()) || !sameBits(s.sweep, t.sweep) || x[i].kind != y[i].kind ||
        x[i].line != y[i].line || a.toolpath.feedOf(i) != b.toolpath.feedOf(i) || x[i].centreForm != y[i].centreForm ||
        x[i].wireOffset != y[i].wireOffset)
      return false;
  }
  return sameDiagnostics(a.diags, b.diags);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kerf::converter;
  PipelineOptions options;
  options.read.maxExecutedBlocks = 200000;  // keep each input fast; the limits themselves are tested
  options.read.maxMoves = 100000;
  // The surface's sections are the checks' costliest part, bounded by levels x budget pieces
  // (1.5 M by default: 0.3 s in Release). Under the sanitizers and coverage a pair test costs about
  // 40 times more: 15 sections of 100,000 pieces took 28 s, and 15 of 10,000 still took 5-9 s on a
  // taper program with 15,552 km of lower contour (tests/fuzz/corpus/sections-15552km.nc), past
  // libFuzzer's 10 s under load. Three sections of at most 2,500 pieces (K0657 past that) take the
  // same code paths.
  options.check.sectionBudget = 2500;
  options.check.surfaceLevels = 4;
  options.centreWords = true;  // explain shows them, below
  std::string text(reinterpret_cast<const char*>(data), size);
  const kerf::test::ScopedThreads three(3);
  const Pipeline p = runPipeline({"fuzz.nc", text}, options);
  if (size > 0 && (data[0] & 6) == 6) {
    const kerf::test::ScopedThreads one(1);
    const Pipeline q = runPipeline({"fuzz.nc", text}, options);
    if (!sameReading(p, q)) __builtin_trap();
  }
  struct {
    const Toolpath& toolpath;
  } a{p.toolpath};
  const SourceFile& src = *p.source;
  Diagnostics diags(20);
  for (const Diagnostic& d : p.diags.all()) (void)formatDiagnostic(d);
  (void)formatTrace(a.toolpath, diags);
  (void)explainText(src, a.toolpath, kerf::geometry::Sampling::step(0.5));
  // The side files a command reads beside a program: the same bytes as a machine profile and as an
  // --offsets table (their readers report, never crash, on any text).
  {
    Diagnostics sideDiags(20);
    (void)parseMachineProfile(src, sideDiags);
    (void)readOffsetTable(src, sideDiags);
  }
  PointRequest request;
  request.maxPoints = 500;
  (void)emitPoints(a.toolpath, &src, bp95dProfile(), request, diags);
  if (a.toolpath.isTaper()) {
    request.sampling = kerf::geometry::Sampling::step(0.5);
    (void)emitPoints4(a.toolpath, &src, bp95dProfile(), request, true, diags);
    if (const auto flat = toolpathAtPlane(a.toolpath, PlaneChoice{PlaneChoice::Kind::Height, 1.0}, 0.01, &src, diags))
      (void)emitPoints(*flat, &src, bp95dProfile(), request, diags);
    if (a.toolpath.heights.known && a.toolpath.moves.size() < 200) {
      std::vector<kerf::geometry::Segment> lower;
      for (const Move& m : a.toolpath.moves) lower.push_back(m.lower);
      kerf::geometry::MeshOptions mo;
      mo.tolerance = 0.1;
      mo.lowerCap = mo.upperCap = true;
      mo.maxCapVertices = 2000;
      mo.maxTriangles = 200000;
      (void)kerf::geometry::meshRuledSurface(lower, a.toolpath.upper, a.toolpath.heights.planes, mo);
    }
  }
  // Polar X/C with the program's own words kept in place (issue 42): from a program without errors
  // (convert writes no other without --force), what it writes reads back with no malformed number
  // and no stray character: the words it makes are well formed, and the ones it copies were.
  if (!p.diags.hasErrors() && !a.toolpath.isTaper() && p.format == InputFormat::Iso &&
      a.toolpath.moves.size() <= 2000) {
    PolarWriteOptions polar;
    polar.tolerance = 0.01;
    polar.sourceBlocks = parseOptionsFor(p.machine);
    if (const auto out = writePolar(a.toolpath, &src, polar, diags)) {
      const Pipeline back = runPipeline({"back.xc", out->text}, options);
      for (const Diagnostic& d : back.diags.all())
        if (d.code == Code::MalformedNumber || d.code == Code::UnexpectedCharacter) __builtin_trap();
    }
  }
  return 0;
}
