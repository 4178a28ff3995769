// kerf cam DRAWING --offset R --side outside|inside --to FORMAT -o OUT: the options mapped onto the
// library's makeAndCheck (converter/convert.h: made, written, read back and checked through the same
// pipeline as `kerf check`), and what it says printed. A program with errors is not written.
#include "commands.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/convert.h"
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

int runCam(const CamArgs& a) {
  using namespace converter;
  const CommonOptions& c = a.common;
  bool ok = true;
  CamRequest r;
  r.cam.start = point(c.reading.start, "--start", ok);
  r.cam.entry = point(a.entry, "--entry", ok);
  const std::optional<geometry::Vec2> shift = point(a.shift, "--shift", ok);
  if (!ok) return kExitUsage;
  const bool controller = a.offsetBy == "controller";
  if (!controller && !c.reading.offset && !a.openPaths) {
    reportError("cam needs --offset R (the wire radius plus the spark gap, mm), or --offset-by controller");
    return kExitUsage;
  }
  // The drawing: read as kerf check reads it, without the wire paths (made by cam, once).
  CommonOptions readOptions = c;
  readOptions.reading.offset.reset();
  readOptions.reading.side.reset();
  readOptions.reading.start.reset();
  std::optional<Loaded> in = load(readOptions, c.input.files.front());
  if (!in) return kExitUsage;
  std::string error;
  if (!pipelineOptions(c, r.readBack, error)) {
    reportError(error);
    return kExitUsage;
  }
  r.cam.offset = c.reading.offset.value_or(0.0);
  r.cam.side = c.reading.side == std::optional<std::string>("inside") ? WireSide::Inside : WireSide::Outside;
  r.cam.controllerOffset = controller;
  r.cam.contour = a.contour;
  r.cam.leadIn = a.leadIn;
  r.cam.openPaths = a.openPaths;
  if (a.direction) r.cam.wireOnLeft = *a.direction == "cw";
  if (shift) r.cam.shift = *shift;
  r.format = a.to;
  r.emit.decimals = a.decimals;
  r.emit.compact = a.compact;
  r.emit.end = a.end == "none" ? std::string() : a.end == "ff" ? std::string("FF") : std::string("DD");
  r.emit.maxPoints = a.maxPoints;
  r.emit.sampling = c.sampling.sampling();
  r.outputName = a.output == "-" ? std::string("<output>") : a.output;

  const CamRun run = makeAndCheck(in->pipeline, r);
  printDiagnostics(run.diags, c);
  if (!run.refusal.empty()) reportError(run.refusal);
  switch (run.status) {
    case WriteStatus::Refused: return kExitUsage;
    case WriteStatus::ProgramErrors:
    case WriteStatus::NotWritten: return kExitErrors;
    case WriteStatus::Written: break;
  }
  if (!writeOutput(a.output, in->inputs, run.output->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  for (const CamContour& k : run.made->contours)
    std::cerr << "kerf: contour " << k.number << ": "
              << (k.open                        ? "open, as drawn"
                  : k.side == WireSide::Outside ? "outside"
                                                : "inside")
              << ", " << k.elements << " elements, " << mm(k.contourLength) << " mm, area " << mm(k.area) << " mm²"
              << (k.open       ? std::string()
                  : controller ? ", offset by the controller"
                               : ", wire path " + mm(k.wireLength) + " mm")
              << "\n";
  std::cerr << "kerf: wrote " << run.output->what << " to "
            << (a.output == "-" ? std::string("standard output") : a.output) << run.output->detail << run.readBack
            << "\n";
  return kExitOk;
}

}  // namespace kerf::cli
