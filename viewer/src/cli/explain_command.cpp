// kerf explain FILE: how each block's geometry follows from its words.
#include "commands.h"
#include "load.h"

#include "kerf/converter/report/report.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace kerf::cli {

CLI::App* addExplainCommand(CLI::App& app, ExplainArgs& a) {
  CLI::App* cmd = app.add_subcommand("explain", "how each block's geometry follows from its words");
  addCommonOptions(*cmd, a.common, false);
  cmd->add_flag("--json", a.json, "machine-readable output on stdout");
  return cmd;
}

int runExplain(const ExplainArgs& a) {
  std::optional<Loaded> in = loadOne(a.common, {.centreWords = true});
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  const auto sampling = a.common.sampling.sampling();
  std::cout << (a.json ? converter::explainJson(*p.source, p.toolpath, sampling, &p.structure)
                       : converter::explainText(*p.source, p.toolpath, sampling, &p.structure));
  return verdictExit(p);
}

}  // namespace kerf::cli
