// Reports: `kerf check` and `kerf explain` as text and as JSON. Strings out, nothing printed.
#pragma once

#include "kerf/converter/nc/program.h"

#include "kerf/converter/cam/cam.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/formats/dxf/read_dxf.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"

#include <string>

namespace kerf::converter {

/// Diagnostics, compiler style, in order, with a closing count line.
std::string formatDiagnosticsText(const Diagnostics& diags);

/// The summary block of `kerf check`.
std::string formatSummaryText(const std::string& file, const Summary& summary, const Diagnostics& diags);

/// `kerf check --json`: {"file", "verdict", "diagnostics": [...], "summary": {...}}; a drawing adds
/// "drawing", and with its wire paths (`wires`, per contour) each closed contour's exact elements
/// and its "wire" (docs/cam.md).
std::string checkReportJson(const std::string& file, const Summary& summary, const Diagnostics& diags,
                            const DrawingResult* drawing = nullptr, const std::vector<ContourWire>* wires = nullptr);

/// A stable, fixed-decimal trace of the Toolpath and the diagnostics (golden files).
std::string formatTrace(const Toolpath& toolpath, const Diagnostics& diags);

/// The contours and passes as one JSON object, as `summary.structure` of checkReportJson holds it
/// (docs/passes.md).
std::string structureJson(const Structure& structure);

/// `kerf explain`: each move, what each word of its block sets (read with `parse`, the machine's
/// parse options), how its geometry follows from them, and the modes in force where they change.
/// With the structure of a program cut in several passes, where each pass begins and ends and
/// which moves lead in and out.
std::string explainText(const SourceFile& source, const Toolpath& toolpath, const geometry::Sampling& sampling,
                        const Structure* structure = nullptr, const ParseOptions& parse = {});
/// `kerf explain --json`: {"file", "sampling", "moves": [{line, kind, start, end, centre, ...}]};
/// with a multi-pass structure each move of a pass has "pass": {contour, pass, role}, role
/// "lead-in", "contour" or "lead-out"; each move's "words" [{word, sets}] and "modes" [sentences].
std::string explainJson(const SourceFile& source, const Toolpath& toolpath, const geometry::Sampling& sampling,
                        const Structure* structure = nullptr, const ParseOptions& parse = {});

}  // namespace kerf::converter
