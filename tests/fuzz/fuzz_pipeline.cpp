// Fuzz entry point for lexer + parser + interpreter + checks + point emitter (libFuzzer ABI).
// Built as a real fuzzer with clang (-DKERF_BUILD_FUZZERS=ON, tests/fuzz/run.sh), and always
// as kerf_fuzz_replay, which feeds it every file of the bad corpus, the samples and
// tests/fuzz/corpus so CI replays what the fuzzer found.
#include "kerf/converter/analysis.h"
#include "kerf/converter/checks.h"
#include "kerf/converter/points.h"
#include "kerf/converter/report.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kerf::converter;
  SourceFile src("fuzz.nc", std::string(reinterpret_cast<const char*>(data), size));
  Diagnostics diags(20);
  InterpreterOptions options;
  options.maxExecutedBlocks = 200000;  // keep each input fast; the limits themselves are tested
  options.maxMoves = 100000;
  const Analysis a = analyse(src, options, diags);
  checkToolpath(a.toolpath, &src, {}, diags);
  for (const Diagnostic& d : diags.all()) (void)formatDiagnostic(d);
  (void)formatTrace(a.toolpath, diags);
  (void)explainText(a.program, a.toolpath, kerf::geometry::Sampling::step(0.5));
  PointRequest request;
  request.maxPoints = 500;
  (void)emitPoints(a.toolpath, &src, bp95dProfile(), request, diags);
  return 0;
}
