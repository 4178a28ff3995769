// The kerf program: parses the command line, runs one command, and turns its result into an exit
// code (0: no errors; 1: the program has errors; 2: a usage or file problem). Each command lives
// in its own file (commands.h) and goes through the one pipeline (converter/pipeline.h).
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/geometry/parallel.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>

int main(int argc, char** argv) {
  // The threads a check may use: the hardware's, at most 16, or KERF_THREADS (1: everything in
  // one thread). Read once, here: the libraries never read the environment.
  kerf::geometry::setWorkerCount(kerf::cli::threadsFromEnvironment());
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
  // When the first argument names a command, only that command is set up (CLI11 checks each new
  // option's names against every other's, a cost paid by every run). Anything else (--help, a
  // misspelt command) sees them all, in this order.
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
  // Output lost on the way (a full disk, a closed pipe) is a failure, whatever the verdict.
  if (std::string error; !finishStandardOutput(error)) {
    reportError(error);
    code = std::max(code, kExitUsage);
  }
  return code;
}
