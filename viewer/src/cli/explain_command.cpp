// kerf explain FILE: how each block's geometry follows from its words.
#include "commands.h"
#include "load.h"

#include "kerf/converter/interpret/machine.h"
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
  const converter::ParseOptions parse = converter::parseOptionsFor(p.machine);  // the words, read again
  std::cout << (a.json ? converter::explainJson(*p.source, p.toolpath, sampling, &p.structure, parse)
                       : converter::explainText(*p.source, p.toolpath, sampling, &p.structure, parse));
  return verdictExit(p);
}

}  // namespace kerf::cli
