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
  converter::CamRequest& r = a.request;
  addWriterOptions(*cmd, r.format, r.emit, group);
  cmd->add_option("-o,--output", a.output, "output file ('-' for standard output)")->group(group);
  cmd->add_option("--contour", r.cam.contour, "cut only this contour (kerf check --json numbers them from 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
      ->group(group);
  addParsed<geometry::Vec2>(
      *cmd, "--entry", "X,Y", pointOption, [&r](const geometry::Vec2& v) { r.cam.entry = v; },
      "the start hole X,Y in mm (one contour): the lead-in comes from there")
      ->group(group);
  cmd->add_option("--lead-in", r.cam.leadIn, "lead-in length in mm when no --entry (default 2)")
      ->check(CLI::Range(0.0, 1000.0))
      ->group(group);
  addChoice<bool>(*cmd, "--offset-by", r.cam.controllerOffset, {{"kerf", false}, {"controller", true}},
                  "kerf: the program is the wire-centre path (--offset applied here); controller: the program is "
                  "the contour with G41/G42 as the machine profile writes them (default kerf)")
      ->group(group);
  addChoice<std::optional<bool>>(*cmd, "--direction", r.cam.wireOnLeft, {{"ccw", false}, {"cw", true}},
                                 "travel round an outside contour: ccw (default: the wire on the right, G42) or cw")
      ->group(group);
  cmd->add_flag("--open-paths", r.cam.openPaths,
                "also cut open contours (a --curve, a profile from the stock's edge) along the drawing, from their "
                "first end, without the offset")
      ->group(group);
  addParsed<geometry::Vec2>(
      *cmd, "--shift", "DX,DY", pointOption, [&r](const geometry::Vec2& v) { r.cam.shift = v; },
      "move the drawing by DX,DY mm first")
      ->group(group);
  return cmd;
}

namespace {

std::string mm(double v) { return converter::formatFixed(v, 3); }

}  // namespace

int runCam(const CamArgs& a) {
  using namespace converter;
  const CommonOptions& c = a.common;
  const ReadOptions& given = c.pipeline.read;
  const bool controller = a.request.cam.controllerOffset;
  if (!controller && !given.wireOffset && !a.request.cam.openPaths) {
    reportError("cam needs --offset R (the wire radius plus the spark gap, mm), or --offset-by controller");
    return kExitUsage;
  }
  // The drawing: read as kerf check reads it, without the wire paths (made by cam, once).
  CommonOptions readOptions = c;
  readOptions.pipeline.read.wireOffset.reset();
  readOptions.pipeline.read.side.reset();
  readOptions.pipeline.read.start.reset();
  std::optional<Loaded> in = load(readOptions, c.input.files.front());
  if (!in) return kExitUsage;
  CamRequest r = a.request;
  std::string error;
  if (!pipelineOptions(c, r.readBack, error)) {
    reportError(error);
    return kExitUsage;
  }
  r.cam.offset = given.wireOffset.value_or(0.0);
  r.cam.side = given.side.value_or(WireSide::Outside);
  r.cam.start = given.start;
  r.emit.points.request.sampling = c.sampling.sampling();
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
