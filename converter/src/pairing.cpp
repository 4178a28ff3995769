#include "kerf/converter/analysis.h"

#include <algorithm>
#include <string>

namespace kerf::converter {

Analysis analyse(const SourceFile& source, const InterpreterOptions& options, Diagnostics& diags) {
  InterpreterOptions io = options;
  auto parseOptionsOf = [](const MachineProfile& m) {
    ParseOptions p;
    p.semicolonEndsBlock = m.semicolonEndsBlock;
    p.upperAxesUZ = m.upperAxesUZ;
    return p;
  };
  // Parsed once with the profile's options; a detected profile that splits blocks differently
  // (Sodick's ';') reads the text again.
  const ParseOptions first = io.machine ? parseOptionsOf(*io.machine) : ParseOptions{};
  Diagnostics parseDiags(std::max<std::size_t>(diags.cap(), 100000));
  Analysis a;
  a.program = parseProgram(source, parseDiags, first);
  if (!io.machine) {
    io.machine = detectMachine(a.program).profile;
    const ParseOptions again = parseOptionsOf(*io.machine);
    if (again.semicolonEndsBlock != first.semicolonEndsBlock || again.upperAxesUZ != first.upperAxesUZ) {
      parseDiags = Diagnostics(std::max<std::size_t>(diags.cap(), 100000));
      a.program = parseProgram(source, parseDiags, again);
    }
  }
  for (const Diagnostic& d : parseDiags.all()) diags.report(d);
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
