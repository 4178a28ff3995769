// `kerf check … --format html -o DIR`: the report a CI job publishes (issue 57). An index with one
// row per program, sortable by each column, and a page per program with its summary and every
// diagnostic as the terminal shows them. Self-contained (no network; the one embedded script and
// style allowed by the pages' Content-Security-Policy, by hash), and everything from the input
// written as text (html.h). The program writes the files; this makes their text.
#pragma once

#include "kerf/converter/check/summary.h"
#include "kerf/converter/nc/diagnostics.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace kerf::converter {

/// One program of the report.
struct HtmlReportEntry {
  std::string name;     ///< as given on the command line
  std::string page;     ///< its page's file name in the report's folder (htmlPageNames)
  int exit = 0;         ///< kerf check's status for it: 0 ok, 1 errors, 2 not read
  std::string failure;  ///< why it was not read
  std::size_t errors = 0, warnings = 0, notes = 0;
  std::string diagnosticsText;  ///< the diagnostics as the terminal shows them (no colour)
  std::string summaryText;      ///< kerf check's text summary (empty: not read)
  const Summary* summary = nullptr;
  /// --drawing: the worst deviation from it and the tolerance, mm; nothing without a drawing.
  std::optional<double> worstDeviation, tolerance;
  /// Files beside the page in the report's folder (empty: not made): a small picture for the
  /// index, the part from above and in iso, and its 3D page.
  std::string thumbnail, top, iso, page3d;
};

/// The file names of the programs' pages: each program's base name with every byte outside
/// [A-Za-z0-9._-] as '_', ".html" added, made unique by "-2", "-3", … in the programs' order
/// ("index.html" is never one of them). Each page <stem>.html keeps <stem>.3d.html free for its
/// 3D page.
std::vector<std::string> htmlPageNames(std::span<const std::string> programs);

/// index.html: the summary line (and `note`, when not empty), then a table of the programs (picture,
/// verdict, errors, warnings, notes, dialect, machine, passes, cut length, cutting time, the
/// drawing's worst deviation), each name a link to its page.
std::string htmlReportIndex(std::span<const HtmlReportEntry> entries, const std::string& summaryLine,
                            const std::string& note = {});

/// A program's page: its verdict, the part from two views with a link to its 3D page, its summary,
/// its passes and its diagnostics, and a link back to the index.
std::string htmlReportPage(const HtmlReportEntry& entry);

}  // namespace kerf::converter
