// The kerf program: parses the command line, runs one command, and turns its result into an exit
// code (0: no errors; 1: the program has errors; 2: a usage or file problem). Each command lives
// in its own file (commands.h) and goes through the one pipeline (converter/pipeline.h).
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/geometry/phase_times.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>

int main(int argc, char** argv) {
  // KERF_PHASE_TIMES=1: where the time went, on standard error at the end (docs/interpreter.md).
  const char* phaseTimes = std::getenv("KERF_PHASE_TIMES");
  const bool timed = phaseTimes && *phaseTimes && std::string_view(phaseTimes) != "0";
  if (timed) {
    kerf::geometry::enablePhaseTimes();
    kerf::geometry::markPhase("main");
  }
  using namespace kerf::cli;
  CLI::App app{"Kerf: verify, explain and convert wire-EDM NC programs"};
  app.name("kerf");  // the help's usage line, whatever path the program was started by
  app.footer(
      "Exit status: 0 no errors (warnings and notes allowed), 1 a program has errors, 2 a usage or file problem; "
      "kerf check of several files exits with the worst.\n"
      "kerf COMMAND --help gives a command's options; docs/diagnostics.md lists the K codes.");
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("kerf ") + KERF_VERSION);

  CheckArgs check;
  ExplainArgs explain;
  ConvertArgs convert;
  RenderArgs render;
  ExportArgs exportArgs;
  ViewArgs view;
  MachinesArgs machines;
  CamArgs cam;
  // When the first argument names a command, only that command is set up: setting up all eight
  // took 0.7 ms of every run (CLI11 checks each new option's names against the others'). Anything
  // else (--help, a misspelt command) sees them all, in this order.
  struct Command {
    std::string_view name;
    std::function<CLI::App*()> add;
    std::function<int()> run;
    CLI::App* app = nullptr;
  };
  Command commands[] = {
      {"check", [&] { return addCheckCommand(app, check); }, [&] { return runCheck(check); }},
      {"explain", [&] { return addExplainCommand(app, explain); }, [&] { return runExplain(explain); }},
      {"convert", [&] { return addConvertCommand(app, convert); }, [&] { return runConvert(convert); }},
      {"render", [&] { return addRenderCommand(app, render); }, [&] { return runRender(render); }},
      {"export", [&] { return addExportCommand(app, exportArgs); }, [&] { return runExport(exportArgs); }},
      {"view", [&] { return addViewCommand(app, view); }, [&] { return runView(view); }},
      {"machines", [&] { return addMachinesCommand(app, machines); }, [&] { return runMachines(machines); }},
      {"cam", [&] { return addCamCommand(app, cam); }, [&] { return runCam(cam); }},
  };
  const std::string_view first = argc > 1 ? std::string_view(argv[1]) : std::string_view();
  const bool named =
      std::any_of(std::begin(commands), std::end(commands), [&](const Command& c) { return c.name == first; });
  for (Command& c : commands)
    if (!named || c.name == first) c.app = c.add();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }
  int code = kExitUsage;
  for (const Command& c : commands)
    if (c.app && *c.app) code = c.run();
  kerf::geometry::markPhase("command");
  // Output lost on the way (a full disk, a closed pipe) is a failure, whatever the verdict.
  if (std::string error; !finishStandardOutput(error)) {
    reportError(error);
    code = std::max(code, kExitUsage);
  }
  if (timed) {
    std::string report =
        "kerf: phase times (ms since main, page faults so far; a phase's figure is taken where it ends)\n";
    char line[160];
    for (const kerf::geometry::PhaseMark& m : kerf::geometry::phaseMarks()) {
      std::snprintf(line, sizeof line, "%10.3f %8ld  %s\n", m.ms, m.minorFaults, m.what);
      report += line;
    }
    std::cerr << report;
  }
  return code;
}
