// The reader fuzz entry points' shared part (fuzz_readers.h).
#include "fuzz_readers.h"

#include "kerf/converter/formats/dxf/write_dxf.h"
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/formats/read.h"

namespace kerf::fuzz {

using namespace kerf::converter;

Pipeline readAs(const std::uint8_t* data, std::size_t size, InputFormat format, const char* name) {
  PipelineOptions options;
  options.read.format = format;
  options.read.maxMoves = 20000;  // elements, spans, records: the limits themselves are tested
  options.read.maxExecutedBlocks = 200000;
  options.check.sectionBudget = 2500;
  options.check.surfaceLevels = 4;
  // Chords within 0.01 mm, not a fixed step: a curve through (2, 1) and (990200, 1) is 2,000 m of
  // path, 4 million points at a step of 0.5 mm, 10 s of sampling under the sanitizers (the summary
  // is linear in the path; its step is tested elsewhere), where the chords take a few thousand.
  options.summarize = geometry::Sampling::tolerance(0.01);
  return runPipeline({name, std::string(reinterpret_cast<const char*>(data), size)}, options);
}

namespace {

/// Reads `text` as `format` and traps when its reader finds it malformed: Kerf wrote it.
void readBack(const std::string& text, InputFormat format, const char* name) {
  PipelineOptions options;
  options.read.format = format;
  options.read.maxMoves = 200000;
  const Pipeline q = runPipeline({name, text}, options);
  for (const Diagnostic& d : q.diags.all())
    if (d.code == Code::DxfSyntax || d.code == Code::ThreeBSyntax || d.code == Code::UnexpectedCharacter ||
        d.code == Code::MalformedNumber)
      __builtin_trap();
}

}  // namespace

void writeAndReadBack(const Pipeline& p) {
  if (!p.read || p.toolpath.moves.empty() || p.toolpath.moves.size() > 5000) return;
  DxfWriteCounts counts;
  const std::string dxf = writeDxf(p.toolpath, DxfWriteOptions{}, &counts);
  if (counts.lines + counts.arcs + counts.circles > 0) readBack(dxf, InputFormat::Dxf, "back.dxf");
  if (p.toolpath.isTaper()) return;  // 3B and ISO of one plane: --plane's business
  Diagnostics diags(100);
  if (const auto threeB = writeThreeB(p.toolpath, p.source.get(), ThreeBWriteOptions{}, diags))
    readBack(threeB->text, InputFormat::ThreeB, "back.3b");
  if (const auto iso = writeIso(p.toolpath, p.source.get(), IsoWriteOptions{}, diags))
    readBack(iso->text, InputFormat::Iso, "back.nc");
}

}  // namespace kerf::fuzz
