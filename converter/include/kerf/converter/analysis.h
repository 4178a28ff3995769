// The reading pipeline every command shares: text -> Program -> Toolpath.
#pragma once

#include "kerf/converter/interpreter.h"
#include "kerf/converter/program.h"
#include "kerf/converter/toolpath.h"

namespace kerf::converter {

struct Analysis {
  Program program;
  Toolpath toolpath;
};

/// Parses and interprets. The source must outlive the result (spans point into it).
inline Analysis analyse(const SourceFile& source, const InterpreterOptions& options, Diagnostics& diags) {
  Analysis a;
  a.program = parseProgram(source, diags);
  a.toolpath = interpret(a.program, options, diags);
  return a;
}

}  // namespace kerf::converter
