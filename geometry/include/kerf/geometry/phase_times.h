// Where a command's time goes: timestamps at the boundaries of its phases (read, parse, interpret,
// the checks' passes), with the page faults taken so far, for measuring speed on a real run
// (`KERF_PHASE_TIMES=1 kerf check part.nc` prints them; docs/interpreter.md, "Measuring").
//
// The program turns the recording on; until then markPhase costs one relaxed load. The marks are
// kept in a fixed table (the first kMostPhaseMarks of a run), so marking never allocates, and any
// thread may mark.
#pragma once

#include <cstddef>
#include <vector>

namespace kerf::geometry {

inline constexpr std::size_t kMostPhaseMarks = 512;

struct PhaseMark {
  const char* what = nullptr;  ///< the phase that ended or began (a string literal)
  double ms = 0.0;             ///< milliseconds since enablePhaseTimes
  long minorFaults = 0;        ///< page faults of the process so far (pages touched for the first time)
};

/// Starts the recording (and its clock). Called once, by the program.
void enablePhaseTimes();
/// Records `what` (a string literal: only the pointer is kept) now, when recording.
void markPhase(const char* what);
/// The marks recorded so far, in the order they were made.
std::vector<PhaseMark> phaseMarks();

}  // namespace kerf::geometry
