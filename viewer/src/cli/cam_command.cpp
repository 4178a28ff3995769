// kerf cam DRAWING --offset R --side outside|inside --to FORMAT -o OUT: a program made from a
// drawing (converter/cam.h), written through the emitter table, then read back and checked through
// the same pipeline as `kerf check` before it is written: a program with errors is not written.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/cam/cam.h"
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/report.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace kerf::cli {

CLI::App* addCamCommand(CLI::App& app, CamArgs& a) {
  CLI::App* cmd = app.add_subcommand("cam", "make a program from a drawing (DXF): contours, wire offset, lead-in");
  addCommonOptions(*cmd, a.common, false);
  const std::string group = "Program";
  std::vector<std::string> names;
  for (const converter::Emitter& e : converter::emitters()) names.emplace_back(e.name);
  cmd->add_option("--to", a.to, "output format (kerf convert --list shows them; default iso)")
      ->check(CLI::IsMember(names))
      ->group(group);
  cmd->add_option("-o,--output", a.output, "output file ('-' for standard output)")->group(group);
  cmd->add_option("--contour", a.contour, "cut only this contour (kerf check --json numbers them from 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
      ->group(group);
  cmd->add_option("--entry", a.entry, "the start hole X,Y in mm (one contour): the lead-in comes from there")
      ->group(group);
  cmd->add_option("--lead-in", a.leadIn, "lead-in length in mm when no --entry (default 2)")
      ->check(CLI::Range(0.0, 1000.0))
      ->group(group);
  cmd->add_option("--offset-by", a.offsetBy,
                  "kerf: the program is the wire-centre path (--offset applied here); controller: the program is "
                  "the contour with G41/G42 as the machine profile writes them (default kerf)")
      ->check(CLI::IsMember({"kerf", "controller"}))
      ->group(group);
  cmd->add_option("--direction", a.direction,
                  "travel round an outside contour: ccw (default: the wire on the right, G42) or cw")
      ->check(CLI::IsMember({"cw", "ccw"}))
      ->group(group);
  cmd->add_flag("--open-paths", a.openPaths,
                "also cut open contours (a --curve, a profile from the stock's edge) along the drawing, from their "
                "first end, without the offset")
      ->group(group);
  cmd->add_option("--shift", a.shift, "move the drawing by DX,DY mm first")->group(group);
  cmd->add_option("--decimals", a.decimals, "iso, polar: digits after the point (default: the machine's)")
      ->check(CLI::Range(0, 6))
      ->group(group);
  cmd->add_flag("--compact", a.compact, "3b, 4b: records without spaces")->group(group);
  cmd->add_option("--end", a.end, "3b, 4b: the end record: dd (default), ff or none")
      ->check(CLI::IsMember({"dd", "ff", "none"}))
      ->group(group);
  cmd->add_option("--max-points", a.maxPoints, "bp95d, points4: controller capacity")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000000}))
      ->group(group);
  return cmd;
}

namespace {

std::optional<geometry::Vec2> point(const std::optional<std::string>& text, const char* option, bool& ok) {
  if (!text) return std::nullopt;
  std::string error;
  std::optional<geometry::Vec2> p = pointOption(*text, option, error);
  if (!p) {
    reportError(error);
    ok = false;
  }
  return p;
}

std::string mm(double v) { return converter::formatFixed(v, 3); }

}  // namespace

/// The program made, read back from its text and checked as kerf check would: `exit` set (after
/// printing why) when it must not be written; `summary` what the last line says of it. The pipeline
/// lives as long as the diagnostics that point into it.
struct ReadBack {
  std::optional<int> exit;
  std::string summary;
  std::optional<converter::Pipeline> pipeline;
};

ReadBack readBackMade(const CamArgs& a, const converter::Pipeline& p, const converter::CamResult& made,
                      const converter::EmitOutput& out, converter::Diagnostics& all) {
  using namespace converter;
  ReadBack r;
  if (a.to != "iso" && a.to != "3b" && a.to != "polar") {
    r.summary = "; this format is not read back";
    return r;
  }
  const CommonOptions& c = a.common;
  const std::string name = a.output == "-" ? std::string("<output>") : a.output;
  PipelineOptions po;
  std::string error;
  CommonOptions checkOptions = c;
  checkOptions.reading = ReadingOptions{};
  checkOptions.reading.format = a.to == "3b" ? "3b" : "iso";
  if (a.to == "3b") checkOptions.reading.start = mm(made.toolpath.start.x()) + "," + mm(made.toolpath.start.y());
  if (!pipelineOptions(checkOptions, po, error)) {
    reportError(error);
    r.exit = kExitUsage;
    return r;
  }
  if (a.to != "3b") po.read.machine = p.machine.name;
  r.pipeline.emplace(runPipeline({name, out.text}, po));
  double length = 0.0;
  for (const Move& m : r.pipeline->toolpath.moves)
    if (m.isCut()) length += m.lower.length();
  const double allowed = 0.002 * static_cast<double>(r.pipeline->toolpath.moves.size()) + 0.01;
  r.summary = "; read back: " + std::to_string(r.pipeline->toolpath.moves.size()) + " moves, cut length " + mm(length) +
              " mm (made " + mm(made.cutLength) + ")";
  const bool lengthOff = std::abs(length - made.cutLength) > allowed;
  // Refused, nothing is written: the findings name the program made, not a file that is not there.
  if (r.pipeline->diags.hasErrors() || lengthOff)
    r.pipeline.emplace(runPipeline({"<not written: " + name + ">", out.text}, po));
  for (const Diagnostic& d : r.pipeline->diags.all())
    if (d.severity != Severity::Note) all.report(d);
  if (r.pipeline->diags.hasErrors()) {
    printDiagnostics(all, c);
    reportError("not writing: the program made has errors when read back (shown above)");
    r.exit = kExitErrors;
  } else if (lengthOff) {
    printDiagnostics(all, c);
    reportError("not writing: read back, the program cuts " + mm(length) + " mm, not the " + mm(made.cutLength) +
                " mm made (more than the output's rounding allows)");
    r.exit = kExitErrors;
  }
  return r;
}

int runCam(const CamArgs& a) {
  using namespace converter;
  const CommonOptions& c = a.common;
  bool ok = true;
  const std::optional<geometry::Vec2> start = point(c.reading.start, "--start", ok);
  const std::optional<geometry::Vec2> entry = point(a.entry, "--entry", ok);
  const std::optional<geometry::Vec2> shift = point(a.shift, "--shift", ok);
  if (!ok) return kExitUsage;
  const bool controller = a.offsetBy == "controller";
  if (!controller && !c.reading.offset && !a.openPaths) {
    reportError("cam needs --offset R (the wire radius plus the spark gap, mm), or --offset-by controller");
    return kExitUsage;
  }
  // The drawing: read as kerf check reads it, without the wire paths (made here, once).
  CommonOptions readOptions = c;
  readOptions.reading.offset.reset();
  readOptions.reading.side.reset();
  readOptions.reading.start.reset();
  std::optional<Loaded> in = load(readOptions, c.input.files.front());
  if (!in) return kExitUsage;
  const Pipeline& p = in->pipeline;
  if (!p.drawing) {
    printDiagnostics(p.diags, c);
    reportError("cam makes a program from a drawing (DXF) or a curve; this file reads as " +
                std::string(inputFormatName(p.format)) + " (kerf convert writes a program for another machine)");
    return kExitUsage;
  }
  Diagnostics all(100000);
  for (const Diagnostic& d : p.diags.all()) all.report(d);
  if (p.diags.hasErrors()) {
    printDiagnostics(all, c);
    reportError("not making a program: the drawing has errors (kerf check shows the same)");
    return kExitErrors;
  }
  CamOptions o;
  o.offset = c.reading.offset.value_or(0.0);
  o.side = c.reading.side == std::optional<std::string>("inside") ? WireSide::Inside : WireSide::Outside;
  o.controllerOffset = controller;
  o.contour = a.contour;
  o.start = start;
  o.entry = entry;
  o.leadIn = a.leadIn;
  o.openPaths = a.openPaths;
  if (a.direction) o.wireOnLeft = *a.direction == "cw";
  if (shift) o.shift = *shift;
  Diagnostics camDiags(100000);
  std::optional<CamResult> made = makeProgram(*p.drawing, p.source.get(), o, camDiags);
  for (const Diagnostic& d : camDiags.all()) all.report(d);
  if (!made || camDiags.hasErrors()) {
    printDiagnostics(all, c);
    reportError("no program made: the drawing's contours cannot be cut as asked");
    return kExitErrors;
  }

  // Through the emitter table, in the machine's conventions.
  const Emitter& emitter = *findEmitter(a.to);
  EmitRequest request;
  request.target = &p.machine;
  request.decimals = a.decimals;
  request.compact = a.compact;
  request.end = a.end == "none" ? std::string() : a.end == "ff" ? std::string("FF") : std::string("DD");
  request.maxPoints = a.maxPoints;
  request.sampling = c.sampling.sampling();
  request.offsetsApplied = true;
  request.flattenSlivers = true;
  Diagnostics emitDiags(100000);
  std::optional<EmitOutput> out = emitter.write(made->toolpath, p.source.get(), request, emitDiags);
  for (const Diagnostic& d : emitDiags.all()) all.report(d);
  if (!out) {
    printDiagnostics(all, c);
    return kExitErrors;
  }

  // Read back what was written, and check it, as kerf check would.
  ReadBack back = readBackMade(a, p, *made, *out, all);
  if (back.exit) return *back.exit;
  printDiagnostics(all, c);
  std::string error;
  if (!writeOutput(a.output, in->inputs, out->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  for (const CamContour& k : made->contours)
    std::cerr << "kerf: contour " << k.number << ": "
              << (k.open                        ? "open, as drawn"
                  : k.side == WireSide::Outside ? "outside"
                                                : "inside")
              << ", " << k.elements << " elements, " << mm(k.contourLength) << " mm, area " << mm(k.area) << " mm²"
              << (k.open       ? std::string()
                  : controller ? ", offset by the controller"
                               : ", wire path " + mm(k.wireLength) + " mm")
              << "\n";
  std::cerr << "kerf: wrote " << out->what << " to " << (a.output == "-" ? std::string("standard output") : a.output)
            << out->detail << back.summary << "\n";
  return kExitOk;
}

}  // namespace kerf::cli
