// kerf convert FILE --to FORMAT: the program for another controller. A program with errors is
// not converted (exit 1, nothing written) unless --force says so.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/points.h"
#include "kerf/converter/report.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace kerf::cli {

CLI::App* addConvertCommand(CLI::App& app, ConvertArgs& a) {
  CLI::App* cmd = app.add_subcommand("convert", "write the program for another controller");
  addCommonOptions(*cmd, a.common, false);
  cmd->add_option("--to", a.to, "output format")
      ->required()
      ->check(CLI::IsMember({"bp95d", "points4"}))
      ->group("Output");
  cmd->add_option("--plane", a.plane, "taper input to bp95d: lower, upper or z=HEIGHT")->group("Output");
  cmd->add_option("--uv", a.uv, "points4: U V as the upper point (absolute) or upper minus lower (relative)")
      ->check(CLI::IsMember({"absolute", "relative"}))
      ->group("Output");
  cmd->add_option("-o,--output", a.output, "output file ('-' for standard output)")->group("Output");
  cmd->add_option("--max-points", a.maxPoints, "controller capacity: choose the step so the output fits")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000000}))
      ->group("Output");
  cmd->add_option("--profile", a.profile, "point-file profile (docs/bp95d.md)")->group("Output");
  cmd->add_option("--start-block", a.startBlock, "start the points at the cut move on this source line")
      ->group("Output");
  cmd->add_flag("--force", a.force, "write the output even when the program has errors (exit 1 all the same)")
      ->group("Output");
  return cmd;
}

int runConvert(const ConvertArgs& a) {
  using namespace converter;
  std::optional<Loaded> in = load(a.common, a.common.input.files.front());
  if (!in) return kExitUsage;
  const Pipeline& p = in->pipeline;
  Diagnostics emitDiags(100000);
  if (p.diags.hasErrors() && !a.force) {
    printDiagnostics(p.diags, a.common);
    reportError("not converting: the program has " + std::to_string(p.diags.errorCount()) +
                (p.diags.errorCount() == 1 ? " error" : " errors") +
                " (kerf check shows the same); --force writes the output anyway");
    return kExitErrors;
  }
  PointProfile profile = bp95dProfile();
  std::optional<SourceFile> profileSource;
  std::vector<std::string> inputs = in->inputs;
  if (a.profile) {
    std::string error;
    std::optional<std::string> text = readTextFile(*a.profile, 1 << 20, error);
    if (!text) {
      reportError(error);
      return kExitUsage;
    }
    inputs.push_back(*a.profile);
    profileSource.emplace(*a.profile, std::move(*text));
    std::optional<PointProfile> parsed = parseProfile(*profileSource, emitDiags);
    if (!parsed) {
      printDiagnostics(emitDiags, a.common);
      return kExitUsage;
    }
    profile = *parsed;
  }
  PointRequest request;
  request.sampling = a.common.sampling.sampling();
  request.maxPoints = a.maxPoints;
  request.startLine = a.startBlock;
  std::optional<PointOutput> out;
  if (a.to == "points4") {
    if (a.plane) {
      reportError("--plane chooses one plane for a 2-axis file; points4 writes both");
      return kExitUsage;
    }
    out = emitPoints4(p.toolpath, p.source.get(), profile, request, a.uv == "relative", emitDiags);
  } else {
    const std::optional<PlaneChoice> plane = parsePlane(a.plane.value_or("lower"));
    if (!plane) {
      reportError("--plane takes lower, upper or z=HEIGHT, not '" + *a.plane + "'");
      return kExitUsage;
    }
    if (p.toolpath.isTaper() && !a.plane) {
      reportError(
          "this is a 4-axis taper program: choose the plane the 2-axis file follows with --plane "
          "lower|upper|z=HEIGHT, or write both with --to points4");
      return kExitUsage;
    }
    const double tol = a.common.sampling.tolerance.value_or(0.001);
    std::optional<Toolpath> flat = toolpathAtPlane(p.toolpath, *plane, tol, p.source.get(), emitDiags);
    if (flat) out = emitPoints(*flat, p.source.get(), profile, request, emitDiags);
  }
  // The program's findings first (as kerf check gives them), then the emitter's.
  Diagnostics all(100000);
  for (const Diagnostic& d : p.diags.all()) all.report(d);
  for (const Diagnostic& d : emitDiags.all()) all.report(d);
  printDiagnostics(all, a.common);
  if (!out) return kExitErrors;
  if (p.diags.hasErrors())  // --force; the point format has no comments to carry the warning
    std::cerr << "kerf: warning: writing a program that has errors, as --force asks\n";
  std::string error;
  if (!writeOutput(a.output, inputs, out->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  const auto& s = out->sampling;
  std::cerr << "kerf: wrote " << out->points << " points (" << profile.name << " profile) to "
            << (a.output == "-" ? std::string("standard output") : a.output) << "; "
            << (s.mode == geometry::SamplingMode::Step ? "step k = " : "tolerance ") << formatFixed(s.value, 6) << " mm"
            << (out->fitted
                    ? " chosen to fit " + std::to_string(a.maxPoints ? *a.maxPoints : *profile.maxPoints) + " points"
                    : "")
            << ", max deviation " << formatFixed(out->stats.maxDeviation, 6) << " mm\n";
  return verdictExit(p);
}

}  // namespace kerf::cli
