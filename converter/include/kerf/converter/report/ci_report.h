// Reports for CI systems: SARIF 2.1.0 (what code-scanning services read) and JUnit XML (what test
// dashboards read), for one or many checked files. docs/ci.md says how to use them.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/structure/passes.h"

#include <span>
#include <string>
#include <vector>

namespace kerf::converter {

/// One diagnostic code as docs/diagnostics.md gives it (the table is compiled in, so the rules a
/// report names are the documented ones).
/// What a report says of one file.
struct CheckedFile {
  std::string name;                      ///< as given on the command line
  const Diagnostics* diags = nullptr;    ///< what the text output shows of it (null: not read)
  std::string failure;                   ///< why it was not read (diags may say more)
  const Structure* structure = nullptr;  ///< its contours and passes (null: not read)
};

/// A SARIF 2.1.0 log: one run, the tool with every documented code as a rule, one result per
/// diagnostic shown (level, message, file, line, column, end column; a geometric finding's 3D
/// point and move in the result's property bag), each file's contours and passes in its
/// artifact's property bag. `version` is Kerf's.
std::string sarifLog(std::span<const CheckedFile> files, const std::string& version);

/// JUnit XML: one testcase per file, a failure listing its errors (warnings and notes in its
/// system-out), an error element for a file that could not be read.
std::string junitReport(std::span<const CheckedFile> files);

}  // namespace kerf::converter
