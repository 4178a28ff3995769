// Reading one program with fixed options: text -> Program -> Toolpath. The commands go through
// pipeline.h, which also decides the conventions from the evidence and runs the checks; this is
// the part of it that tests and benchmarks call with options of their own.
#pragma once

#include "kerf/converter/interpret/interpreter.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/toolpath.h"

namespace kerf::converter {

struct Analysis {
  Program program;
  Toolpath toolpath;
};

/// Parses and interprets. The source must outlive the result (spans point into it). With no
/// machine in the options, the profile is detected from the program (machine.h); the integer unit
/// and arc-centre convention are the options' either way.
Analysis analyse(const SourceFile& source, const InterpreterOptions& options, Diagnostics& diags);

/// Two-file input (`kerf check lower.nc --upper upper.nc`): both programs read as plain 2-axis
/// programs, the second one's moves become the upper contour of the first's, move by move. A
/// different move count is an error (K0220) naming the first move without a partner; the
/// heights come from the first program or the options (K0217 when neither gives them).
void pairUpper(Toolpath& lower, const Toolpath& upper, const SourceFile* lowerSource, const SourceFile* upperSource,
               Diagnostics& diags);

}  // namespace kerf::converter
