// Geometric checks of a Toolpath: findings reported as diagnostics with a move and a point.
#pragma once

#include "kerf/converter/diagnostics.h"
#include "kerf/converter/toolpath.h"

namespace kerf::converter {

struct CheckOptions {
  double tolerance = 1e-6;  ///< mm: points closer than this coincide
  std::size_t maxContacts = 64;
};

/// Runs the 2-axis checks on the cut moves (rapids are not cut):
///  - K0601/K0602/K0603 the cut path crosses, touches or overlaps itself (exact on lines and arcs);
///    K0604 (note) the lead-out retraces the lead-in;
///  - K0605 the cut path never closes a loop;  K0606 nothing is cut;
///  - K0607 a rapid between cuts (a point-driven machine would cut along it).
void checkToolpath(const Toolpath& toolpath, const SourceFile* source, const CheckOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
