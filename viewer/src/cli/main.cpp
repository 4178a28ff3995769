// The kerf program: parses the command line, runs one command, and turns its result into an exit
// code (0: no errors; 1: the program has errors; 2: a usage or file problem). Each command lives
// in its own file (commands.h) and goes through the one pipeline (converter/pipeline.h).
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iterator>
#include <string_view>

int main(int argc, char** argv) {
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
  // took a millisecond of every run (CLI11 checks each new option's names against the others'),
  // a fiftieth of checking a 6 MB program. Anything else (--help, a misspelt command) sees them all.
  static constexpr std::string_view kCommands[] = {"check",  "explain", "convert",  "render",
                                                   "export", "view",    "machines", "cam"};
  const std::string_view first = argc > 1 ? std::string_view(argv[1]) : std::string_view();
  const bool named = std::find(std::begin(kCommands), std::end(kCommands), first) != std::end(kCommands);
  auto wanted = [&](std::string_view name) { return !named || first == name; };
  CLI::App* checkCmd = wanted("check") ? addCheckCommand(app, check) : nullptr;
  CLI::App* explainCmd = wanted("explain") ? addExplainCommand(app, explain) : nullptr;
  CLI::App* convertCmd = wanted("convert") ? addConvertCommand(app, convert) : nullptr;
  CLI::App* renderCmd = wanted("render") ? addRenderCommand(app, render) : nullptr;
  CLI::App* exportCmd = wanted("export") ? addExportCommand(app, exportArgs) : nullptr;
  CLI::App* viewCmd = wanted("view") ? addViewCommand(app, view) : nullptr;
  CLI::App* machinesCmd = wanted("machines") ? addMachinesCommand(app, machines) : nullptr;
  CLI::App* camCmd = wanted("cam") ? addCamCommand(app, cam) : nullptr;

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
  if (checkCmd && *checkCmd) code = runCheck(check);
  if (explainCmd && *explainCmd) code = runExplain(explain);
  if (convertCmd && *convertCmd) code = runConvert(convert);
  if (renderCmd && *renderCmd) code = runRender(render);
  if (exportCmd && *exportCmd) code = runExport(exportArgs);
  if (viewCmd && *viewCmd) code = runView(view);
  if (machinesCmd && *machinesCmd) code = runMachines(machines);
  if (camCmd && *camCmd) code = runCam(cam);
  // Output lost on the way (a full disk, a closed pipe) is a failure, whatever the verdict.
  if (std::string error; !finishStandardOutput(error)) {
    reportError(error);
    code = std::max(code, kExitUsage);
  }
  return code;
}
