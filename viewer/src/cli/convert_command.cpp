// kerf convert FILE --to FORMAT: the program for another controller. A program with errors is
// not converted (exit 1, nothing written) unless --force says so.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/formats/emit.h"
#include "kerf/converter/formats/points/points.h"
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
  std::vector<std::string> names;
  for (const converter::Emitter& e : converter::emitters()) names.emplace_back(e.name);
  cmd->add_flag("--list", a.list, "list the output formats and exit")->group("Output");
  cmd->add_option("--to", a.to, "output format (--list shows them)")->check(CLI::IsMember(names))->group("Output");
  cmd->add_option("--plane", a.plane,
                  "taper input to a 2-axis format: lower, upper or z=HEIGHT; points4: guides (X Y at the lower guide, "
                  "U V at the upper)")
      ->group("Output");
  cmd->add_option("--uv", a.uv, "points4: U V as the upper point (absolute) or upper minus lower (relative)")
      ->check(CLI::IsMember({"absolute", "relative"}))
      ->group("Output");
  cmd->add_option("-o,--output", a.output, "output file ('-' for standard output)")->group("Output");
  cmd->add_option("--max-points", a.maxPoints, "controller capacity: choose the step so the output fits")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000000}))
      ->group("Output");
  cmd->add_option("--profile", a.profile, "point-file profile (docs/bp95d.md)")->group("Output");
  cmd->add_option("--pass", a.pass,
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
  cmd->add_option("--start-block", a.startBlock, "start the output at the cut move on this source line")
      ->group("Output");
  cmd->add_option("--for", a.target,
                  "iso: write for this machine's conventions (a built-in profile name or a profile file; default "
                  "generic)")
      ->group("Output");
  cmd->add_option("--decimals", a.decimals, "iso, polar: digits after the decimal point (default 3)")
      ->check(CLI::Range(0, 6))
      ->group("Output");
  cmd->add_flag("--compact", a.compact, "3b, 4b: records without spaces (B9900B0B9900GXL1)")->group("Output");
  cmd->add_option("--end", a.end, "3b, 4b: the end record: dd (default), ff or none")
      ->check(CLI::IsMember({"dd", "ff", "none"}))
      ->group("Output");
  cmd->add_option("--polar-x-out", a.polarXOut, "polar: X as a diameter (default) or a radius")
      ->check(CLI::IsMember({"diameter", "radius"}))
      ->group("Output");
  cmd->add_flag("--force", a.force, "write the output even when the program has errors (exit 1 all the same)")
      ->group("Output");
  return cmd;
}

namespace {

/// --pass N: the toolpath of each contour's Nth pass; nothing, said, when no contour has one.
std::optional<converter::Toolpath> passToConvert(const converter::Pipeline& p, const std::string& pass) {
  std::optional<converter::Toolpath> out =
      converter::toolpathOfPass(p.toolpath, p.structure, std::stoul(pass), p.checkOptions.tolerance);
  if (!out) {
    std::size_t most = 0;
    for (const converter::Contour& c : p.structure.contours) most = std::max(most, c.passes.size());
    reportError("--pass " + pass + ": no contour of this program has a pass " + pass + " (" +
                (most == 1 ? std::string("each is cut in one pass") : "the most is " + std::to_string(most)) + ")");
  }
  return out;
}

/// The emitter settings from the options, and from the program read (polar keeps an ISO source's
/// blocks).
void fillRequest(const ConvertArgs& a, const converter::Pipeline& p, converter::EmitRequest& request) {
  request.sampling = a.common.sampling.sampling();
  request.maxPoints = a.maxPoints;
  request.startLine = a.startBlock;
  request.relativeUv = a.uv == "relative";
  request.atGuides = a.plane == "guides";
  request.decimals = a.decimals;
  request.compact = a.compact;
  request.end = a.end == "none" ? std::string() : a.end == "ff" ? std::string("FF") : std::string("DD");
  request.polarX = a.polarXOut == "radius" ? converter::PolarX::Radius : converter::PolarX::Diameter;
  request.tolerance = a.common.sampling.tolerance.value_or(0.001);
  // The whole program as its own blocks wrote it: polar output keeps what it does not convert.
  if (p.format == converter::InputFormat::Iso && a.pass == "all" && !p.toolpath.isTaper())
    request.sourceBlocks = converter::parseOptionsFor(p.machine);
}

/// The plane a 2-axis format follows (`plane` stays empty for an emitter that writes both); false
/// after saying why the options do not fit the emitter or the program.
bool planeFor(const ConvertArgs& a, const converter::Emitter& emitter, const converter::Toolpath& toolpath,
              std::optional<converter::PlaneChoice>& plane) {
  if (emitter.planes == converter::PlaneNeed::Both) {
    if (!a.plane || (*a.plane == "guides" && std::string_view(emitter.name) == "points4")) return true;
    reportError("--plane chooses one plane for a 2-axis file; " + std::string(emitter.name) + " writes both" +
                (std::string_view(emitter.name) == "points4" ? " (or both guides: --plane guides)" : ""));
    return false;
  }
  plane = converter::parsePlane(a.plane.value_or("lower"));
  if (!plane) {
    reportError("--plane takes lower, upper or z=HEIGHT (|HEIGHT| up to 1e6 mm), not '" + *a.plane + "'");
    return false;
  }
  if (toolpath.isTaper() && !a.plane) {
    reportError(
        "this is a 4-axis taper program: choose the plane the 2-axis file follows with --plane "
        "lower|upper|z=HEIGHT (one file per plane), or write both with --to points4 or --to iso");
    return false;
  }
  return true;
}

void printList() {
  std::cout << "Output formats (kerf convert FILE --to NAME -o OUT):\n";
  for (const converter::Emitter& e : converter::emitters())
    std::cout << "  " << e.name << std::string(9 - std::min<std::size_t>(8, e.name.size()), ' ') << e.summary
              << (e.planes == converter::PlaneNeed::One ? " [one plane: --plane for a taper program]"
                                                        : " [both planes]")
              << "\n";
}

}  // namespace

int runConvert(const ConvertArgs& a) {
  using namespace converter;
  if (a.list) {
    printList();
    return kExitOk;
  }
  if (a.common.input.files.empty() || a.to.empty()) {
    reportError(a.common.input.files.empty() ? "convert needs a program (or --list)"
                                             : "convert needs --to FORMAT (kerf convert --list shows them)");
    return kExitUsage;
  }
  const Emitter& emitter = *findEmitter(a.to);
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
  EmitRequest request;
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
    request.profile = *parsed;
  }
  std::optional<MachineProfile> targetFile;
  std::optional<SourceFile> targetSource;
  if (a.target) {
    if (const MachineProfile* m = findBuiltinMachine(*a.target)) {
      request.target = m;
    } else {
      std::string error;
      std::optional<std::string> text = readTextFile(*a.target, 1 << 20, error);
      if (!text) {
        reportError("--for '" + *a.target +
                    "' is neither a built-in machine (kerf machines lists them) nor a file: " + error);
        return kExitUsage;
      }
      inputs.push_back(*a.target);
      targetSource.emplace(*a.target, std::move(*text));
      targetFile = parseMachineProfile(*targetSource, emitDiags);
      if (!targetFile) {
        printDiagnostics(emitDiags, a.common);
        return kExitUsage;
      }
      request.target = &*targetFile;
    }
  }
  fillRequest(a, p, request);

  const Toolpath* path = &p.toolpath;
  std::optional<Toolpath> onePass;
  if (a.pass != "all") {
    onePass = passToConvert(p, a.pass);
    if (!onePass) return kExitUsage;
    path = &*onePass;
  }
  std::optional<Toolpath> flat;
  std::optional<PlaneChoice> plane;
  if (!planeFor(a, emitter, p.toolpath, plane)) return kExitUsage;
  if (plane) {
    flat = toolpathAtPlane(*path, *plane, a.common.sampling.tolerance.value_or(0.001), p.source.get(), emitDiags);
    path = flat ? &*flat : nullptr;
  }
  std::optional<EmitOutput> out;
  if (path) out = emitter.write(*path, p.source.get(), request, emitDiags);
  // The program's findings first (as kerf check gives them), then the emitter's.
  Diagnostics all(100000);
  for (const Diagnostic& d : p.diags.all()) all.report(d);
  for (const Diagnostic& d : emitDiags.all()) all.report(d);
  printDiagnostics(all, a.common);
  if (!out) return kExitErrors;
  if (p.diags.hasErrors())  // --force; not every format has comments to carry the warning
    std::cerr << "kerf: warning: writing a program that has errors, as --force asks\n";
  std::string error;
  if (!writeOutput(a.output, inputs, out->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << out->what << " to " << (a.output == "-" ? std::string("standard output") : a.output)
            << out->detail << "\n";
  return verdictExit(p);
}

}  // namespace kerf::cli
