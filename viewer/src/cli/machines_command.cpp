// kerf machines [show NAME]: the built-in machine profiles, to read and to copy.
#include "commands.h"
#include "load.h"

#include "kerf/converter/interpret/machine.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

namespace kerf::cli {

CLI::App* addMachinesCommand(CLI::App& app, MachinesArgs& a) {
  CLI::App* cmd = app.add_subcommand("machines", "the built-in machine profiles (docs/machines.md)");
  CLI::App* show = cmd->add_subcommand("show", "print a profile, to copy and edit for --machine FILE");
  show->add_option("name", a.show, "the profile's name")->required();
  return cmd;
}

int runMachines(const MachinesArgs& a) {
  const auto& all = converter::builtinMachines();
  if (a.show) {
    const converter::MachineProfile* m = converter::findBuiltinMachine(*a.show);
    if (!m) {
      reportError("there is no built-in machine profile named '" + *a.show + "' (kerf machines lists them)");
      return kExitUsage;
    }
    std::cout << m->text;
    return kExitOk;
  }
  std::size_t width = 0;
  for (const auto& m : all) width = std::max(width, m.name.size());
  for (const auto& m : all) std::cout << m.name << std::string(width + 2 - m.name.size(), ' ') << m.summary << "\n";
  std::cout << "\nkerf machines show NAME prints a profile; kerf check FILE --machine NAME|FILE reads with one.\n";
  return kExitOk;
}

}  // namespace kerf::cli
