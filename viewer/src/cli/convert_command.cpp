// kerf convert FILE --to FORMAT: the program for another controller. A program with errors is
// not converted (exit 1, nothing written) unless --force says so.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/convert.h"
#include "kerf/converter/report/report.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <iostream>

namespace kerf::cli {

CLI::App* addConvertCommand(CLI::App& app, ConvertArgs& a) {
  CLI::App* cmd = app.add_subcommand("convert", "write the program for another controller");
  addCommonOptions(*cmd, a.common, false);
  a.common.input.fileRequired = false;  // not with --list
  converter::ConvertRequest& r = a.request;
  addWriterOptions(*cmd, r.format, r.emit, "Output");
  cmd->add_flag("--list", a.list, "list the output formats and exit")->group("Output");
  cmd->add_option("--plane", r.plane,
                  "taper input to a 2-axis format: lower, upper or z=HEIGHT; points4: guides (X Y at the lower guide, "
                  "U V at the upper)")
      ->group("Output");
  addChoice<bool>(*cmd, "--uv", r.emit.points.relativeUv, {{"absolute", false}, {"relative", true}},
                  "points4: U V as the upper point (absolute) or upper minus lower (relative)")
      ->group("Output");
  cmd->add_option("-o,--output", a.output, "output file ('-' for standard output)")->group("Output");
  cmd->add_option("--profile", a.profile, "point-file profile (docs/bp95d.md)")->group("Output");
  cmd->add_option_function<std::string>(
         "--pass",
         [&r](const std::string& v) {
           if (v == "all")
             r.pass.reset();
           else
             r.pass = std::stoul(v);
         },
         "all (default: every pass in order) or N: of each contour only its Nth pass (1: the rough cut), "
         "joined by rapids (docs/passes.md)")
      ->check([](const std::string& v) {
        if (v == "all") return std::string();
        std::size_t n = 0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        return ec == std::errc() && end == v.data() + v.size() && n >= 1 && n <= 255
                   ? std::string()
                   : std::string("--pass takes all or a pass number from 1 to 255");
      })
      ->group("Output");
  cmd->add_option("--start-block", r.emit.startLine, "start the output at the cut move on this source line")
      ->group("Output");
  cmd->add_option("--for", a.target,
                  "iso: write for this machine's conventions (a built-in profile name or a profile file; default "
                  "generic)")
      ->group("Output");
  addChoice<converter::PolarX>(*cmd, "--polar-x-out", r.emit.polar.polarX,
                               {{"diameter", converter::PolarX::Diameter}, {"radius", converter::PolarX::Radius}},
                               "polar: X as a diameter (default) or a radius")
      ->group("Output");
  cmd->add_flag("--force", r.force, "write the output even when the program has errors (exit 1 all the same)")
      ->group("Output");
  return cmd;
}

namespace {

void printList() {
  std::cout << "Output formats (kerf convert FILE --to NAME -o OUT):\n";
  for (const converter::Emitter& e : converter::emitters())
    std::cout << "  " << e.name << std::string(9 - std::min<std::size_t>(8, e.name.size()), ' ') << e.summary
              << (e.planes == converter::PlaneNeed::One ? " [one plane: --plane for a taper program]"
                                                        : " [both planes]")
              << "\n";
}

/// The files the options name (--profile, --for FILE) read into the request, and the sampling;
/// false (said) when one cannot be read.
bool readNamedFiles(const ConvertArgs& a, std::vector<std::string>& inputs, converter::ConvertRequest& r) {
  using namespace converter;
  std::string error;
  if (a.profile) {
    std::optional<std::string> text = readTextFile(*a.profile, 1 << 20, error);
    if (!text) {
      reportError(error);
      return false;
    }
    inputs.push_back(*a.profile);
    r.pointProfile = SourceText{*a.profile, std::move(*text)};
  }
  if (a.target && findBuiltinMachine(*a.target)) {
    r.target = a.target;
  } else if (a.target) {
    std::optional<std::string> text = readTextFile(*a.target, 1 << 20, error);
    if (!text) {
      reportError("--for '" + *a.target +
                  "' is neither a built-in machine (kerf machines lists them) nor a file: " + error);
      return false;
    }
    inputs.push_back(*a.target);
    r.targetFile = SourceText{*a.target, std::move(*text)};
  }
  r.tolerance = a.common.sampling.tolerance.value_or(0.001);
  r.emit.points.request.sampling = a.common.sampling.sampling();
  r.emit.polar.tolerance = r.tolerance;
  return true;
}

}  // namespace

int runConvert(const ConvertArgs& a) {
  using namespace converter;
  if (a.list) {
    printList();
    return kExitOk;
  }
  if (a.common.input.files.empty() || a.request.format.empty()) {
    reportError(a.common.input.files.empty() ? "convert needs a program (or --list)"
                                             : "convert needs --to FORMAT (kerf convert --list shows them)");
    return kExitUsage;
  }
  std::optional<Loaded> in = load(a.common, a.common.input.files.front());
  if (!in) return kExitUsage;
  const Pipeline& p = in->pipeline;
  ConvertRequest request = a.request;
  if (!readNamedFiles(a, in->inputs, request)) return kExitUsage;
  const Conversion c = convert(p, request);
  printDiagnostics(c.diags, a.common);
  switch (c.status) {
    case WriteStatus::ProgramErrors:
      reportError("not converting: the program has " + std::to_string(p.diags.errorCount()) +
                  (p.diags.errorCount() == 1 ? " error" : " errors") +
                  " (kerf check shows the same); --force writes the output anyway");
      return kExitErrors;
    case WriteStatus::Refused: return kExitUsage;
    case WriteStatus::NotWritten: return kExitErrors;
    case WriteStatus::Written: break;
  }
  if (p.diags.hasErrors())  // --force; not every format has comments to carry the warning
    std::cerr << "kerf: warning: writing a program that has errors, as --force asks\n";
  std::string error;
  if (!writeOutput(a.output, in->inputs, c.output->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << c.output->what << " to "
            << (a.output == "-" ? std::string("standard output") : a.output) << c.output->detail << "\n";
  return verdictExit(p);
}

}  // namespace kerf::cli
