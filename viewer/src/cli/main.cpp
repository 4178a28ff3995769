// The kerf program: parses the command line, runs one command, and turns its result into an exit
// code (0: no errors; 1: the program has errors; 2: a usage or file problem). Each command lives
// in its own file (commands.h) and goes through the one pipeline (converter/pipeline.h).
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include <CLI/CLI.hpp>

#include <algorithm>

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
  CLI::App* checkCmd = addCheckCommand(app, check);
  CLI::App* explainCmd = addExplainCommand(app, explain);
  CLI::App* convertCmd = addConvertCommand(app, convert);
  CLI::App* renderCmd = addRenderCommand(app, render);
  CLI::App* exportCmd = addExportCommand(app, exportArgs);
  CLI::App* viewCmd = addViewCommand(app, view);
  CLI::App* machinesCmd = addMachinesCommand(app, machines);
  CLI::App* camCmd = addCamCommand(app, cam);

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
  if (*checkCmd) code = runCheck(check);
  if (*explainCmd) code = runExplain(explain);
  if (*convertCmd) code = runConvert(convert);
  if (*renderCmd) code = runRender(render);
  if (*exportCmd) code = runExport(exportArgs);
  if (*viewCmd) code = runView(view);
  if (*machinesCmd) code = runMachines(machines);
  if (*camCmd) code = runCam(cam);
  // Output lost on the way (a full disk, a closed pipe) is a failure, whatever the verdict.
  if (std::string error; !finishStandardOutput(error)) {
    reportError(error);
    code = std::max(code, kExitUsage);
  }
  return code;
}
