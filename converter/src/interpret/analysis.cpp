#include "kerf/converter/interpret/analysis.h"

#include <algorithm>
#include <string>

namespace kerf::converter {

Analysis analyse(const SourceFile& source, const InterpreterOptions& options, Diagnostics& diags) {
  MachineReading r = readForMachine(source, options.machine);
  for (const Diagnostic& d : r.diags.all()) diags.report(d);
  InterpreterOptions io = options;
  io.machine = r.machine;
  Analysis a;
  a.program = std::move(r.program);
  a.toolpath = interpret(a.program, io, diags);
  return a;
}

void pairUpper(Toolpath& lower, const Toolpath& upper, const SourceFile* lowerSource, const SourceFile* upperSource,
               Diagnostics& diags) {
  for (const auto& [tp, src] :
       {std::pair<const Toolpath*, const SourceFile*>{&lower, lowerSource}, {&upper, upperSource}}) {
    if (tp->dialect != Dialect::Plain) {
      diags.error(Code::TwoFileNotPlain, src, SourceSpan::wholeFile(),
                  std::string("two-file input pairs two 2-axis programs, and this one is ") + dialectName(tp->dialect));
      return;
    }
  }
  const std::size_t n = lower.moves.size(), m = upper.moves.size();
  if (n != m) {
    const bool lowerLonger = n > m;
    const std::size_t first = std::min(n, m);
    const Move& extra = lowerLonger ? lower.moves[first] : upper.moves[first];
    diags.error(Code::BlockCountMismatch, lowerLonger ? lowerSource : upperSource, extra.span,
                "the lower program has " + std::to_string(n) + " moves and the upper one " + std::to_string(m) +
                    ": this move has no partner on the " + (lowerLonger ? "upper" : "lower") + " plane",
                "the two contours are paired block by block: give both the same number of moves");
    return;
  }
  lower.dialect = Dialect::TwoFile;
  lower.upper.reserve(n);
  for (const Move& mv : upper.moves) lower.upper.push_back(mv.lower);
  if (!lower.heights.known) {
    diags.error(Code::HeightsMissing, lowerSource, SourceSpan::wholeFile(),
                "two-file input needs the heights of the two planes, and none are given",
                "give --thickness H or --upper-z Z");
  }
}

}  // namespace kerf::converter
