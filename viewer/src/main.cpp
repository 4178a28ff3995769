// The kerf program: turns library results into output and exit codes.
//   exit 0: no errors (warnings allowed)   1: the program has errors   2: usage or I/O problem
#include "kerf/converter/analysis.h"
#include "kerf/converter/checks.h"
#include "kerf/converter/dialect.h"
#include "kerf/converter/interpreter.h"
#include "kerf/converter/points.h"
#include "kerf/converter/program.h"
#include "kerf/converter/report.h"
#include "kerf/converter/summary.h"

#include "file_io.h"
#include "kerf/export/mesh_export.h"
#include "kerf/headless/context.h"
#include "kerf/render/scene.h"
#include "ui/picture.h"
#include "window/window.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace {

using namespace kerf::converter;

constexpr int kExitOk = 0;
constexpr int kExitErrors = 1;
constexpr int kExitUsage = 2;

struct CommonOptions {
  std::string input;
  std::string integerUnit = "mm";
  std::string arcCentre = "incremental";
  std::optional<double> offset;
  std::optional<double> step;
  std::optional<double> tolerance;
  std::size_t maxDiagnostics = 50;
  bool json = false;
  // 4-axis taper
  std::string dialect = "auto";
  std::optional<double> lowerZ, upperZ, thickness, programZ;
  std::optional<std::string> upperFile;
};

void addCommon(CLI::App& cmd, CommonOptions& o, bool withJson) {
  cmd.add_option("file", o.input, "NC program (ISO G-code)")->required();
  cmd.add_option("--integer-unit", o.integerUnit, "unit of coordinates written without a decimal point")
      ->check(CLI::IsMember({"mm", "um"}));
  cmd.add_option("--arc-centre", o.arcCentre, "how I J give an arc's centre")
      ->check(CLI::IsMember({"incremental", "reversed", "absolute"}));
  cmd.add_option("--offset", o.offset, "wire offset in mm for G41/G42 without D or H (recorded, not applied yet)");
  auto* step = cmd.add_option("--step", o.step, "arc interpolation step k in mm (chord length; default 0.1)")
                   ->check(CLI::PositiveNumber);
  auto* tol = cmd.add_option("--tolerance", o.tolerance, "arc chord tolerance in mm (max deviation), instead of --step")
                  ->check(CLI::PositiveNumber);
  step->excludes(tol);
  cmd.add_option("--max-diagnostics", o.maxDiagnostics, "show at most this many diagnostics")
      ->check(CLI::Range(1, 100000));
  if (withJson) cmd.add_flag("--json", o.json, "machine-readable output on stdout");
  cmd.add_option("--dialect", o.dialect, "4-axis dialect (docs/taper.md); auto: detected from the words")
      ->check(CLI::IsMember({"auto", "plain", "xyuv-abs", "xyuv-rel", "sodick-colon", "taper-angle"}));
  cmd.add_option("--lower-z", o.lowerZ, "z of the lower contour's plane, mm (default 0)");
  auto* upperZ = cmd.add_option("--upper-z", o.upperZ, "z of the upper contour's plane, mm");
  auto* thickness =
      cmd.add_option("--thickness", o.thickness, "upper minus lower plane, mm")->check(CLI::PositiveNumber);
  upperZ->excludes(thickness);
  cmd.add_option("--program-z", o.programZ, "z of the programmed contour (taper-angle, xyuv-rel), mm");
  cmd.add_option("--upper", o.upperFile, "two-file input: the upper contour's program, paired move by move");
}

kerf::geometry::Sampling samplingOf(const CommonOptions& o) {
  if (o.tolerance) return kerf::geometry::Sampling::tolerance(*o.tolerance);
  return kerf::geometry::Sampling::step(o.step.value_or(0.1));
}

InterpreterOptions interpreterOptions(const CommonOptions& o) {
  InterpreterOptions io;
  io.integerUnit = o.integerUnit == "um" ? IntegerUnit::Micrometre : IntegerUnit::Millimetre;
  io.arcCentre = o.arcCentre == "reversed"   ? ArcCentreMode::Reversed
                 : o.arcCentre == "absolute" ? ArcCentreMode::Absolute
                                             : ArcCentreMode::Incremental;
  io.wireOffset = o.offset;
  io.dialect = parseDialect(o.dialect);
  io.lowerZ = o.lowerZ;
  io.upperZ = o.upperZ;
  io.thickness = o.thickness;
  io.programZ = o.programZ;
  return io;
}

/// Everything a command needs after reading and interpreting the input.
struct Loaded {
  std::optional<SourceFile> source;
  std::optional<SourceFile> upperSource;
  Program program;
  Toolpath toolpath;
};

bool load(const CommonOptions& o, Diagnostics& diags, Loaded& out) {
  std::string error;
  std::optional<std::string> text = kerf::cli::readTextFile(o.input, SourceFile::kMaxSize, error);
  if (!text) {
    std::cerr << "kerf: error: " << error << "\n";
    return false;
  }
  out.source.emplace(o.input, std::move(*text));
  InterpreterOptions io = interpreterOptions(o);
  if (o.upperFile) io.dialect = Dialect::Plain;
  Analysis a = analyse(*out.source, io, diags);
  out.program = std::move(a.program);
  out.toolpath = std::move(a.toolpath);
  if (o.upperFile) {
    std::optional<std::string> upperText = kerf::cli::readTextFile(*o.upperFile, SourceFile::kMaxSize, error);
    if (!upperText) {
      std::cerr << "kerf: error: " << error << "\n";
      return false;
    }
    out.upperSource.emplace(*o.upperFile, std::move(*upperText));
    const Analysis upper = analyse(*out.upperSource, io, diags);
    pairUpper(out.toolpath, upper.toolpath, &*out.source, &*out.upperSource, diags);
  }
  return true;
}

void printDiagnostics(Diagnostics& diags) {
  diags.sortByPosition();
  std::cerr << formatDiagnosticsText(diags);
}

struct CheckCommand {
  double maxTaper = 30.0;
  std::optional<double> uvRange;
};

int runCheck(const CommonOptions& o, const CheckCommand& c) {
  Diagnostics diags(o.maxDiagnostics);
  Loaded in;
  if (!load(o, diags, in)) return kExitUsage;
  CheckOptions options;
  options.maxTaperDegrees = c.maxTaper;
  options.uvRange = c.uvRange;
  const SurfaceMeasures measures = measureSurface(in.toolpath);
  checkToolpath(in.toolpath, &*in.source, options, diags, &measures);
  const Summary summary = summarize(in.program, in.toolpath, samplingOf(o), &measures);
  diags.sortByPosition();
  if (o.json) {
    std::cout << checkReportJson(o.input, summary, diags);
  } else {
    std::cerr << formatDiagnosticsText(diags);
    std::cout << formatSummaryText(o.input, summary, diags);
  }
  return diags.hasErrors() ? kExitErrors : kExitOk;
}

/// Everything the pictures, the window and the export show: the program, its findings, the scene.
struct Checked {
  Loaded in;
  Diagnostics diags{100000};
  std::size_t errors = 0, warnings = 0;
};

bool loadAndCheck(const CommonOptions& o, Checked& c) {
  if (!load(o, c.diags, c.in)) return false;
  const SurfaceMeasures measures = measureSurface(c.in.toolpath);
  checkToolpath(c.in.toolpath, &*c.in.source, CheckOptions{}, c.diags, &measures);
  c.diags.sortByPosition();
  c.errors = c.diags.errorCount();
  c.warnings = c.diags.warningCount();
  // What the terminal shows is capped as for check; the picture gets every finding.
  Diagnostics shown(o.maxDiagnostics);
  for (const auto& d : c.diags.all()) shown.report(d);
  std::cerr << formatDiagnosticsText(shown);
  return true;
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

kerf::ui::Annotation annotationOf(const CommonOptions& o, const Checked& c) {
  kerf::ui::Annotation a;
  a.title = baseName(o.input);
  const Toolpath& tp = c.in.toolpath;
  a.subtitle =
      std::string(tp.isTaper() ? dialectName(tp.dialect) : "2-axis") + " | " + std::to_string(tp.moves.size()) +
      " moves | " +
      (c.errors ? std::to_string(c.errors) + (c.errors == 1 ? " error" : " errors") : std::string("no errors")) +
      (c.warnings ? ", " + std::to_string(c.warnings) + (c.warnings == 1 ? " warning" : " warnings") : std::string());
  return a;
}

kerf::render::SceneOptions sceneOptionsOf(std::optional<double> meshTolerance,
                                          std::optional<std::size_t> generators = {}) {
  kerf::render::SceneOptions so;
  if (meshTolerance) so.tolerance = *meshTolerance;
  if (generators) so.generators = *generators;
  return so;
}

struct PictureOptions {
  std::string output;
  std::string view = "iso";
  std::string size = "800x600";
  std::optional<std::string> colourBy;
  bool highlight = false;
  std::string backend = "auto";
  int samples = 0;
  std::optional<double> meshTolerance;
  std::optional<std::size_t> generators;
  bool timings = false;
};

bool parseSize(const std::string& text, int& w, int& h) {
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &w, &h, &consumed) != 2 || consumed != static_cast<int>(text.size()))
    return false;
  return w >= 16 && h >= 16 && w <= 8192 && h <= 8192;
}

int runRender(const CommonOptions& o, const PictureOptions& p) {
  kerf::ui::PictureRequest request;
  if (!parseSize(p.size, request.width, request.height)) {
    std::cerr << "kerf: error: --size takes WIDTHxHEIGHT between 16 and 8192, not '" << p.size << "'\n";
    return kExitUsage;
  }
  request.view = *kerf::render::parseView(p.view);
  request.backend = *kerf::headless::parseBackend(p.backend);
  request.samples = p.samples;
  request.options.colourBySlope = p.colourBy.has_value();
  request.options.highlightFindings = p.highlight;
  Checked c;
  if (!loadAndCheck(o, c)) return kExitUsage;
  const kerf::render::Scene scene =
      kerf::render::buildScene(c.in.toolpath, c.diags.all(), sceneOptionsOf(p.meshTolerance, p.generators));
  request.annotation = annotationOf(o, c);
  request.annotation.legend = request.options.colourBySlope;
  request.annotation.labels = p.highlight;
  const kerf::ui::PictureResult result = kerf::ui::renderPicture(scene, request);
  if (result.png.empty()) {
    std::cerr << "kerf: error: " << result.error << "\n";
    return kExitUsage;
  }
  std::string error;
  if (!kerf::cli::writeOutput(p.output, o.input, result.png, error)) {
    std::cerr << "kerf: error: " << error << "\n";
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << request.width << "x" << request.height << " " << kerf::render::viewName(request.view)
            << " view (" << scene.triangles() << " triangles) to " << p.output << "\n";
  if (p.timings)
    std::cerr << "kerf: " << result.context << "; context " << formatFixed(result.contextSeconds, 3) << " s, upload "
              << formatFixed(result.uploadSeconds, 3) << " s, draw+read " << formatFixed(result.drawSeconds, 3)
              << " s, PNG " << formatFixed(result.encodeSeconds, 3) << " s\n";
  return c.errors ? kExitErrors : kExitOk;
}

struct ExportOptions {
  std::string output;
  std::optional<double> meshTolerance;
  bool caps = false;
};

int runExport(const CommonOptions& o, const ExportOptions& e) {
  const auto format = kerf::exporter::formatOfPath(e.output);
  if (!format) {
    std::cerr << "kerf: error: -o must end in .vtp, .stl or .ply, not '" << e.output << "'\n";
    return kExitUsage;
  }
  Checked c;
  if (!loadAndCheck(o, c)) return kExitUsage;
  const kerf::exporter::SurfaceData data =
      kerf::exporter::surfaceData(c.in.toolpath, c.diags.all(), sceneOptionsOf(e.meshTolerance), e.caps);
  if (data.surface.mesh.triangles.empty()) {
    std::cerr << "kerf: error: nothing is cut, so there is no surface to export\n";
    return kExitErrors;
  }
  std::string error;
  const bool written = kerf::cli::writeOutputVia(
      e.output, o.input,
      [&](const std::string& tmp, std::string& err) { return kerf::exporter::writeMesh(data, *format, tmp, err); },
      error);
  if (!written) {
    std::cerr << "kerf: error: " << error << "\n";
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << data.surface.mesh.triangles.size() << " triangles, "
            << data.surface.mesh.vertices.size() << " points to " << e.output
            << (data.surface.mesh.truncated ? " (incomplete: triangle limit reached)" : "") << "\n";
  return c.errors ? kExitErrors : kExitOk;
}

struct ViewOptions {
  std::optional<std::string> screenshot;
  int frames = 0;
  std::string size = "1280x800";
  bool benchmark = false;
  std::optional<std::size_t> line;
  double playback = -1;
  std::optional<double> meshTolerance;
  std::optional<std::size_t> generators;
  bool colourBy = false;
  bool coarse = false;
};

int runView(const CommonOptions& o, const ViewOptions& v) {
  kerf::window::WindowRequest request;
  if (!parseSize(v.size, request.width, request.height)) {
    std::cerr << "kerf: error: --size takes WIDTHxHEIGHT between 16 and 8192, not '" << v.size << "'\n";
    return kExitUsage;
  }
  if (v.screenshot && v.frames <= 0) {
    std::cerr << "kerf: error: --screenshot needs --frames N: the window is saved after N frames\n";
    return kExitUsage;
  }
  Checked c;
  if (!loadAndCheck(o, c)) return kExitUsage;
  const kerf::render::Scene scene =
      kerf::render::buildScene(c.in.toolpath, c.diags.all(), sceneOptionsOf(v.meshTolerance, v.generators));
  request.source = &*c.in.source;
  request.toolpath = &c.in.toolpath;
  request.findings = c.diags.all();
  request.scene = &scene;
  request.sceneOptions = sceneOptionsOf(v.meshTolerance, v.generators);
  request.coarseFrames = v.coarse;
  request.annotation = annotationOf(o, c);
  request.annotation.legend = true;
  request.options.colourBySlope = v.colourBy;
  request.step = o.step.value_or(0.1);
  request.screenshot = v.screenshot;
  request.frames = v.frames;
  request.benchmark = v.benchmark;
  request.selectLine = v.line;
  request.playback = v.playback;
  std::string error;
  if (!kerf::window::runWindow(request, error)) {
    std::cerr << "kerf: error: " << error << "\n";
    return kExitUsage;
  }
  return c.errors ? kExitErrors : kExitOk;
}

int runExplain(const CommonOptions& o) {
  Diagnostics diags(o.maxDiagnostics);
  Loaded in;
  if (!load(o, diags, in)) return kExitUsage;
  printDiagnostics(diags);
  const auto sampling = samplingOf(o);
  std::cout << (o.json ? explainJson(in.program, in.toolpath, sampling)
                       : explainText(in.program, in.toolpath, sampling));
  return diags.hasErrors() ? kExitErrors : kExitOk;
}

struct ConvertOptions {
  std::string to;
  std::optional<std::string> plane;
  std::string uv = "absolute";
  std::string output = "-";
  std::optional<std::size_t> maxPoints;
  std::optional<std::string> profile;
  std::optional<std::uint32_t> startBlock;
};

int runConvert(const CommonOptions& o, const ConvertOptions& c) {
  Diagnostics diags(o.maxDiagnostics);
  Loaded in;
  if (!load(o, diags, in)) return kExitUsage;
  if (diags.hasErrors()) {
    printDiagnostics(diags);
    std::cerr << "kerf: error: not converting a program with errors\n";
    return kExitErrors;
  }
  PointProfile profile = bp95dProfile();
  std::optional<SourceFile> profileSource;
  if (c.profile) {
    std::string error;
    std::optional<std::string> text = kerf::cli::readTextFile(*c.profile, 1 << 20, error);
    if (!text) {
      std::cerr << "kerf: error: " << error << "\n";
      return kExitUsage;
    }
    profileSource.emplace(*c.profile, std::move(*text));
    std::optional<PointProfile> parsed = parseProfile(*profileSource, diags);
    if (!parsed) {
      printDiagnostics(diags);
      return kExitUsage;
    }
    profile = *parsed;
  }
  PointRequest request;
  request.sampling = samplingOf(o);
  request.maxPoints = c.maxPoints;
  request.startLine = c.startBlock;
  std::optional<PointOutput> out;
  if (c.to == "points4") {
    if (c.plane) {
      std::cerr << "kerf: error: --plane chooses one plane for a 2-axis file; points4 writes both\n";
      return kExitUsage;
    }
    out = emitPoints4(in.toolpath, &*in.source, profile, request, c.uv == "relative", diags);
  } else {
    const std::optional<PlaneChoice> plane = parsePlane(c.plane.value_or("lower"));
    if (!plane) {
      std::cerr << "kerf: error: --plane takes lower, upper or z=HEIGHT, not '" << *c.plane << "'\n";
      return kExitUsage;
    }
    if (in.toolpath.isTaper() && !c.plane) {
      std::cerr << "kerf: error: this is a 4-axis taper program: choose the plane the 2-axis file follows with "
                   "--plane lower|upper|z=HEIGHT, or write both with --to points4\n";
      return kExitUsage;
    }
    const double tol = o.tolerance.value_or(0.001);
    std::optional<Toolpath> flat = toolpathAtPlane(in.toolpath, *plane, tol, &*in.source, diags);
    if (flat) out = emitPoints(*flat, &*in.source, profile, request, diags);
  }
  printDiagnostics(diags);
  if (!out) return kExitErrors;
  std::string error;
  if (!kerf::cli::writeOutput(c.output, o.input, out->text, error)) {
    std::cerr << "kerf: error: " << error << "\n";
    return kExitUsage;
  }
  const auto& s = out->sampling;
  std::cerr << "kerf: wrote " << out->points << " points (" << profile.name << " profile) to "
            << (c.output == "-" ? std::string("standard output") : c.output) << "; "
            << (s.mode == kerf::geometry::SamplingMode::Step ? "step k = " : "tolerance ") << formatFixed(s.value, 6)
            << " mm"
            << (out->fitted
                    ? " chosen to fit " + std::to_string(c.maxPoints ? *c.maxPoints : *profile.maxPoints) + " points"
                    : "")
            << ", max deviation " << formatFixed(out->stats.maxDeviation, 6) << " mm\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Kerf: verify, explain and convert wire-EDM NC programs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "kerf 0.1.0");

  CommonOptions check, explain, convert, render, exportCommon, view;
  PictureOptions picture;
  ExportOptions exportOnly;
  ViewOptions viewOnly;
  ConvertOptions conv;
  CheckCommand checkOnly;
  auto* checkCmd = app.add_subcommand("check", "verify a program: diagnostics, geometric findings, summary");
  addCommon(*checkCmd, check, true);
  checkCmd->add_option("--max-taper", checkOnly.maxTaper, "the machine's largest wire slope, degrees (default 30)")
      ->check(CLI::Range(0.0, 89.0));
  checkCmd->add_option("--uv-range", checkOnly.uvRange, "largest U/V travel from the lower guide, mm")
      ->check(CLI::PositiveNumber);
  auto* explainCmd = app.add_subcommand("explain", "how each block's geometry follows from its words");
  addCommon(*explainCmd, explain, true);
  auto* convertCmd = app.add_subcommand("convert", "write the program for another controller");
  addCommon(*convertCmd, convert, false);
  convertCmd->add_option("--to", conv.to, "output format")->required()->check(CLI::IsMember({"bp95d", "points4"}));
  convertCmd->add_option("--plane", conv.plane, "taper input to bp95d: lower, upper or z=HEIGHT");
  convertCmd->add_option("--uv", conv.uv, "points4: U V as the upper point (absolute) or upper minus lower (relative)")
      ->check(CLI::IsMember({"absolute", "relative"}));
  convertCmd->add_option("-o,--output", conv.output, "output file ('-' for standard output)");
  convertCmd->add_option("--max-points", conv.maxPoints, "controller capacity: choose the step so the output fits")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000000}));
  convertCmd->add_option("--profile", conv.profile, "point-file profile (docs/bp95d.md)");
  convertCmd->add_option("--start-block", conv.startBlock, "start the points at the cut move on this source line");

  auto* renderCmd = app.add_subcommand("render", "a picture of the part as PNG, with no display and no GPU");
  addCommon(*renderCmd, render, false);
  renderCmd->add_option("-o,--output", picture.output, "PNG file to write")->required();
  renderCmd->add_option("--view", picture.view, "iso, top, front or side")
      ->check(CLI::IsMember({"iso", "top", "front", "side"}));
  renderCmd->add_option("--size", picture.size, "WIDTHxHEIGHT in pixels (default 800x600)");
  renderCmd->add_option("--color-by,--colour-by", picture.colourBy, "colour the surface by the wire slope")
      ->check(CLI::IsMember({"slope"}));
  renderCmd->add_flag("--highlight-findings", picture.highlight, "tint moves with findings and label the findings");
  renderCmd->add_option("--backend", picture.backend, "headless OpenGL: auto (OSMesa, then EGL), osmesa or egl")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
  renderCmd
      ->add_option("--samples", picture.samples,
                   "multisampling (1: none; default 4, or 1 when the triangles outnumber half the pixels)")
      ->check(CLI::Range(1, 16));
  renderCmd
      ->add_option("--mesh-tolerance", picture.meshTolerance,
                   "largest distance of the drawn surface from the exact one, mm (default 0.01)")
      ->check(CLI::Range(1e-5, 100.0));
  renderCmd->add_flag("--timings", picture.timings, "print the time of each stage");
  renderCmd
      ->add_option("--generators", picture.generators, "about this many wire lines along the cut (default 72; 0: none)")
      ->check(CLI::Range(std::size_t{0}, std::size_t{100000}));

  auto* exportCmd = app.add_subcommand("export", "the ruled surface as a .vtp, .stl or .ply mesh (VTK)");
  addCommon(*exportCmd, exportCommon, false);
  exportCmd->add_option("-o,--output", exportOnly.output, "mesh file to write: .vtp, .stl or .ply")->required();
  exportCmd
      ->add_option("--mesh-tolerance", exportOnly.meshTolerance,
                   "largest distance of the mesh from the exact surface, mm (default 0.01)")
      ->check(CLI::Range(1e-5, 100.0));
  exportCmd->add_flag("--caps", exportOnly.caps, "close closed contours with flat caps (a solid for CAD)");

  auto* viewCmd = app.add_subcommand("view", "the interactive window: program text, 3D part and findings");
  addCommon(*viewCmd, view, false);
  viewCmd->add_option("--screenshot", viewOnly.screenshot, "save the window as PNG after --frames frames, then close");
  viewCmd->add_option("--frames", viewOnly.frames, "draw this many frames, then close")->check(CLI::Range(1, 1000000));
  viewCmd->add_option("--size", viewOnly.size, "window size WIDTHxHEIGHT (default 1280x800)");
  viewCmd->add_flag("--benchmark", viewOnly.benchmark, "print frame times when closing");
  viewCmd->add_option("--line", viewOnly.line, "select the move on this source line");
  viewCmd->add_option("--playback", viewOnly.playback, "show the wire at this fraction of the path, 0 to 1")
      ->check(CLI::Range(0.0, 1.0));
  viewCmd
      ->add_option("--mesh-tolerance", viewOnly.meshTolerance,
                   "largest distance of the drawn surface from the exact one, mm")
      ->check(CLI::Range(1e-5, 100.0));
  viewCmd->add_flag("--coarse", viewOnly.coarse, "draw every frame as while the view moves (with --benchmark)");
  viewCmd->add_option("--generators", viewOnly.generators, "about this many wire lines along the cut (default 72)")
      ->check(CLI::Range(std::size_t{0}, std::size_t{100000}));
  viewCmd->add_flag("--color-by-slope,--colour-by-slope", viewOnly.colourBy,
                    "start with the surface coloured by slope");

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
  if (*checkCmd) return runCheck(check, checkOnly);
  if (*explainCmd) return runExplain(explain);
  if (*renderCmd) return runRender(render, picture);
  if (*exportCmd) return runExport(exportCommon, exportOnly);
  if (*viewCmd) return runView(view, viewOnly);
  return runConvert(convert, conv);
}
