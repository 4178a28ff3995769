// kerf check FILE... : diagnostics, geometric findings and the part's numbers, for each file.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/report.h"
#include "kerf/converter/summary.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

namespace kerf::cli {

CLI::App* addCheckCommand(CLI::App& app, CheckArgs& a) {
  CLI::App* cmd = app.add_subcommand("check", "verify programs: diagnostics, geometric findings, summary");
  addCommonOptions(*cmd, a.common, true);
  auto* json =
      cmd->add_flag("--json", a.json, "machine-readable output on stdout (an array when several files are checked)");
  cmd->add_flag(
         "--trace", a.trace,
         "the toolpath and every diagnostic in a stable fixed-decimal text on stdout (golden files, bug reports)")
      ->excludes(json);
  return cmd;
}

int runCheck(const CheckArgs& a) {
  int worst = kExitOk;
  std::string jsonArray;
  const bool many = a.common.input.files.size() > 1;
  if (a.common.input.upper && many) {
    reportError("--upper pairs one lower program with one upper program: give a single file with it");
    return kExitUsage;
  }
  if (std::count(a.common.input.files.begin(), a.common.input.files.end(), "-") > 1) {
    reportError("standard input ('-') can be read only once");
    return kExitUsage;
  }
  for (const std::string& file : a.common.input.files) {
    // The text is needed again only for quotes, except by --trace (it prints each move's words).
    std::optional<Loaded> in = load(a.common, file, {.quoteOnly = !a.trace, .summary = true});
    if (!in) {
      worst = std::max(worst, kExitUsage);
      continue;
    }
    const converter::Pipeline& p = in->pipeline;
    const converter::Summary& summary = *p.summary;  // load() asked for it, and the program was read
    const converter::Diagnostics shown = capped(p.diags, a.common.checks.maxDiagnostics);
    if (a.trace) {
      std::cout << converter::formatTrace(p.toolpath, p.diags);
    } else if (a.json) {
      std::string one = converter::checkReportJson(displayName(file), summary, shown, p.drawing ? &*p.drawing : nullptr,
                                                   p.wires.empty() ? nullptr : &p.wires);
      while (!one.empty() && one.back() == '\n') one.pop_back();
      if (many)
        jsonArray += (jsonArray.empty() ? "[\n" : ",\n") + one;
      else
        std::cout << one << "\n";
    } else {
      std::cerr << converter::formatDiagnosticsText(shown);
      std::cout << converter::formatSummaryText(displayName(file), summary, shown);
    }
    worst = std::max(worst, verdictExit(p));
  }
  if (a.json && many) std::cout << (jsonArray.empty() ? "[" : jsonArray) << "\n]\n";
  return worst;
}

}  // namespace kerf::cli
