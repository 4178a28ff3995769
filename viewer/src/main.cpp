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

#include <CLI/CLI.hpp>

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

  CommonOptions check, explain, convert;
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
  return runConvert(convert, conv);
}
