// The options of the kerf program, each declared once (options.h).
// Sections: 1. the option groups  2. values given as text  3. the pipeline's options
#include "options.h"

#include "kerf/converter/report/ci_report.h"

#include "file_io.h"
#include "kerf/converter/interpret/dialect.h"
#include "kerf/converter/interpret/machine.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace kerf::cli {

// ---- 1. the option groups -----------------------------------------------------------------------

geometry::Sampling SamplingOptions::sampling() const {
  if (tolerance) return geometry::Sampling::tolerance(*tolerance);
  return geometry::Sampling::step(step.value_or(kDefaultStep));
}

std::vector<std::string> builtinMachineNames() {
  std::vector<std::string> names;
  for (const converter::MachineProfile& m : converter::builtinMachines()) names.push_back(m.name);
  return names;
}

namespace {

/// A length that must be greater than zero and within a kilometre (every coordinate Kerf reads
/// is), said in words (CLI::PositiveNumber prints its range to the largest double: 300 digits).
const CLI::Validator kPositiveLength(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !std::isfinite(v) || v <= 0)
        return "must be a length greater than 0 mm, not " + text;
      if (v > 1e6) return "must be a length of at most 1e6 mm (a kilometre), not " + text;
      return {};
    },
    "MM > 0");

}  // namespace

namespace {

/// The input group: the files, --files-from, --curve, --max-input, --upper, --machine.
void addInputOptions(CLI::App& cmd, InputOptions& o, bool manyFiles) {
  // The file is required unless --curve stands in for it (checked once everything is parsed).
  if (manyFiles) {
    cmd.add_option("files", o.files, "NC programs or folders of them ('-' reads a program from standard input)");
    cmd.add_option("--files-from", o.filesFrom,
                   "read the files to check from this list, one a line: files, folders or glob patterns (* ? [...]); "
                   "'-' reads the list from standard input")
        ->group("Input");
  } else
    cmd.add_option("file", o.files, "NC program ('-' reads standard input)")->expected(0, 1);
  cmd.add_option("--curve", o.curve,
                 "a curve instead of a file: \"x = EXPR; y = EXPR\" of the parameter t (muparser), fitted with "
                 "biarcs (docs/cam.md)")
      ->group("Input");
  cmd.add_option("--t", o.range, "the curve's range FROM:TO (expressions, e.g. 0:2*pi)")->group("Input");
  cmd.add_option("--max-input", o.maxInputMiB,
                 "the largest program read, MiB (default 512; a larger one is refused before it is read)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{2047}))
      ->group("Input");
  cmd.final_callback([&o, manyFiles] {
    if (o.curve) {
      if (!o.files.empty()) throw CLI::ValidationError("--curve", "give a file or --curve, not both");
      o.files = {kCurveInput};
    } else if (o.range) {
      throw CLI::ValidationError("--t", "--t is the range of a --curve");
    } else if (o.files.empty() && o.fileRequired && !o.filesFrom) {
      throw CLI::RequiredError(manyFiles ? "files" : "file");
    }
  });
  cmd.add_option("--upper", o.upper, "two-file input: the upper contour's program, paired move by move")
      ->group("Input");
  cmd.add_option("--machine", o.machine,
                 "machine profile: a built-in name (kerf machines lists them) or a profile file; "
                 "default: detected from the program")
      ->group("Input");
}

std::optional<std::array<double, 2>> heightsOption(const std::string& text, const char* option, std::string& error);

/// The reading group: what the words mean: format, conventions, offsets, heights. Bound to the
/// library's ReadOptions; --offsets names a file, read with the others (pipelineOptions).
void addReadingOptions(CLI::App& cmd, converter::ReadOptions& r, OptionFiles& files) {
  using namespace converter;
  const std::string reading = "Reading (default: the machine profile's, else the program's evidence)";
  addChoice<std::optional<InputFormat>>(cmd, "--input-format", r.format,
                                        {{"auto", std::nullopt},
                                         {"iso", InputFormat::Iso},
                                         {"3b", InputFormat::ThreeB},
                                         {"dxf", InputFormat::Dxf},
                                         {"curve", InputFormat::Curve}},
                                        "input format; auto: detected from the content (docs/formats.md)")
      ->group(reading);
  addParsed<geometry::Vec2>(
      cmd, "--start", "X,Y", pointOption, [&r](const geometry::Vec2& v) { r.start = v; },
      "where a 3B program starts, X,Y in mm (default: where its --upper program starts, else 0,0)")
      ->group(reading);
  addChoice<std::optional<bool>>(
      cmd, "--polar-x", r.polarXDiameter, {{"radius", false}, {"diameter", true}},
      "X inside G12.1/G112 polar interpolation: radius or diameter (default: the machine profile's)")
      ->group(reading);
  addChoice<std::optional<double>>(
      cmd, "--dxf-units", r.dxfUnit, {{"mm", 1.0}, {"in", 25.4}, {"file", 0.0}},
      "a DXF drawing's unit: file (the default: as its $INSUNITS says, unitless read as mm), or mm or in "
      "whatever it says (docs/dxf.md)")
      ->group(reading);
  cmd.add_option("--curve-tolerance", r.curveTolerance,
                 "curves (--curve, a .curve file, DXF SPLINE and ELLIPSE) as biarcs within this, mm (default 0.001)")
      ->check(CLI::Range(1e-6, 10.0))
      ->group(reading);
  cmd.add_option("--chain-tolerance", r.chainTolerance,
                 "a DXF drawing's element ends this close (mm) are one point of a contour (default 0.001)")
      ->check(CLI::Range(1e-9, 10.0))
      ->group(reading);
  addChoice<std::optional<bool>>(
      cmd, "--polar-frame", r.polarFrameTable, {{"tool", false}, {"table", true}},
      "the G12.1/G112 frame: tool (turned by the table's C at G12.1, as Fanuc says) or table (the "
      "table at C 0, as seed 002's post means); default: the machine profile's")
      ->group(reading);
  addChoice<std::optional<IntegerUnit>>(cmd, "--integer-unit", r.integerUnit,
                                        {{"mm", IntegerUnit::Millimetre}, {"um", IntegerUnit::Micrometre}},
                                        "unit of coordinates written without a decimal point")
      ->group(reading);
  addChoice<std::optional<ArcCentreMode>>(cmd, "--arc-centre", r.arcCentre,
                                          {{arcCentreName(ArcCentreMode::Incremental), ArcCentreMode::Incremental},
                                           {arcCentreName(ArcCentreMode::Reversed), ArcCentreMode::Reversed},
                                           {arcCentreName(ArcCentreMode::Absolute), ArcCentreMode::Absolute}},
                                          "how I J give an arc's centre")
      ->group(reading);
  cmd.add_option("--offset", r.wireOffset,
                 "wire offset in mm (wire radius plus spark gap): for G41/G42 without D or H; for a drawing "
                 "with --side, its wire path")
      ->check(CLI::Range(0.0, 100.0))
      ->group(reading);
  cmd.add_option("--offsets", files.offsets,
                 "an offset table file, one register a line (H001 = 0.180, mm): the values of G41/G42 D.. or H.. "
                 "the program's own table does not give (docs/passes.md)")
      ->group(reading);
  addChoice<std::optional<WireSide>>(
      cmd, "--side", r.side, {{"outside", WireSide::Outside}, {"inside", WireSide::Inside}},
      "a drawing's wire side with --offset: outside (a punch) or inside (a die) of the outermost "
      "contours; holes in them get the other side")
      ->group(reading);
  std::vector<std::pair<std::string, std::optional<Dialect>>> dialects = {{"auto", std::nullopt}};
  for (const Dialect d : {Dialect::Plain, Dialect::XyuvAbs, Dialect::XyuvRel, Dialect::XyuvLinuxCnc,
                          Dialect::SodickColon, Dialect::TaperAngle})
    dialects.emplace_back(dialectName(d), d);
  addChoice(cmd, "--dialect", r.dialect, dialects, "4-axis dialect (docs/taper.md); auto: detected from the words")
      ->group(reading);
  addChoice<std::optional<bool>>(cmd, "--upper-axes", r.upperAxesUZ, {{"uv", false}, {"uz", true}},
                                 "names of the second plane's axes: uv, or uz (some hot-wire firmware)")
      ->group(reading);
  // Heights within a kilometre, as every coordinate Kerf reads (docs/formats.md).
  const auto kHeight = CLI::Range(-1e6, 1e6);
  cmd.add_option("--lower-z", r.lowerZ, "z of the lower contour's plane, mm (default 0)")
      ->check(kHeight)
      ->group(reading);
  auto* upperZ =
      cmd.add_option("--upper-z", r.upperZ, "z of the upper contour's plane, mm")->check(kHeight)->group(reading);
  auto* thickness =
      cmd.add_option("--thickness", r.thickness, "upper minus lower plane, mm")->check(kPositiveLength)->group(reading);
  upperZ->excludes(thickness);
  cmd.add_option("--program-z", r.programZ, "z of the programmed contour (taper-angle, xyuv-rel), mm")
      ->check(kHeight)
      ->group(reading);
  addParsed<std::array<double, 2>>(
      cmd, "--guides", "LOWER_Z,UPPER_Z", heightsOption, [&r](const std::array<double, 2>& v) { r.guides = v; },
      "LOWER_Z,UPPER_Z: the wire guides' heights, mm, the part's lower face at 0 (default: the program's "
      "M100 P Q, else the machine profile's guides)")
      ->group(reading);
  addParsed<std::array<double, 2>>(
      cmd, "--workpiece", "Z0,Z1", heightsOption, [&r](const std::array<double, 2>& v) { r.workpiece = v; },
      "Z0,Z1: the work's faces, mm, where the program's planes are the machine's (a hot-wire foam "
      "cutter's carriages): the part is the wire's cut between them, the planes become the guides")
      ->group(reading);
}

/// The check group: the machine's limits, the time estimate's speed and the drawing, bound to the
/// library's options (--drawing and --drawing-upper name files); which diagnostics show and how.
void addCheckOptions(CLI::App& cmd, converter::PipelineOptions& p, OptionFiles& files, CheckOptions& o) {
  const std::string checks = "Checks (default: the machine profile's limits)";
  cmd.add_option("--max-taper", p.check.maxTaperDegrees, "the machine's largest wire slope, degrees (generic: 30)")
      ->check(CLI::Range(0.0, 89.0))
      ->group(checks);
  cmd.add_option("--uv-range", p.check.uvRange, "largest U/V travel from the lower guide, mm")
      ->check(kPositiveLength)
      ->group(checks);
  cmd.add_option("--speed", p.check.speed,
                 "cutting speed of every cut for the time estimate, mm/min (default: the machine profile's speed "
                 "model, docs/passes.md)")
      ->check(CLI::Range(0.001, 100000.0))
      ->group(checks);
  cmd.add_option(
         "--drawing", files.drawing,
         "the drawing (DXF) the program should cut: each element against the part edge, both ways (docs/drawing.md)")
      ->group(checks);
  cmd.add_option("--drawing-tolerance", p.drawingCheck.tolerance,
                 "how far the part edge may lie from the drawing, mm (default 0.005)")
      ->check(CLI::Range(1e-6, 100.0))
      ->group(checks);
  addParsed<geometry::Vec2>(
      cmd, "--drawing-origin", "X,Y", pointOption, [&p](const geometry::Vec2& v) { p.drawingCheck.origin = v; },
      "the drawing's point at the program's origin, X,Y in mm (default 0,0)")
      ->group(checks);
  cmd.add_option("--drawing-layer", p.drawingCheck.layer,
                 "compare only this layer of the drawing (default: every layer)")
      ->group(checks);
  cmd.add_option("--drawing-upper", files.drawingUpper,
                 "a taper program's upper plane against this drawing (DXF), each plane with its own deviations")
      ->group(checks);
  cmd.add_option("--drawing-upper-layer", p.drawingCheck.upperLayer,
                 "the upper plane against this layer (of --drawing-upper, or of --drawing when it is not given)")
      ->group(checks);
  cmd.add_flag("--align", p.drawingCheck.align,
               "place the drawing where it fits the part edge best (a turn and a shift, or a mirror), and say where")
      ->group(checks);
  cmd.add_option("--max-diagnostics", o.maxDiagnostics, "show at most this many diagnostics (default 50)")
      ->check(CLI::Range(1, 100000))
      ->group(checks);
  cmd.add_option("-W", o.codeOptions,
                 "-Wno-K0604 silences a warning or note, -Werror=K0650 makes a code an error, -Werror every warning "
                 "(as compilers take them; errors cannot be silenced)")
      ->allow_extra_args(false)
      ->group(checks);
  cmd.add_flag("-q,--quiet", o.quiet, "print errors only")->group(checks);
  cmd.add_option("--color", o.color,
                 "colour the diagnostics: auto (on a terminal, unless NO_COLOR is set), always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->group(checks);
}

/// The sampling group: how arcs are sampled: --step or --tolerance.
void addSamplingOptions(CLI::App& cmd, SamplingOptions& o) {
  auto* step = cmd.add_option("--step", o.step, "arc interpolation step k in mm (chord length; default 0.1)")
                   ->check(kPositiveLength)
                   ->group("Sampling");
  auto* tol = cmd.add_option("--tolerance", o.tolerance, "arc chord tolerance in mm (max deviation), instead of --step")
                  ->check(kPositiveLength)
                  ->group("Sampling");
  step->excludes(tol);
}

}  // namespace

void addCommonOptions(CLI::App& cmd, CommonOptions& o, bool manyFiles) {
  addInputOptions(cmd, o.input, manyFiles);
  addReadingOptions(cmd, o.pipeline.read, o.files);
  addCheckOptions(cmd, o.pipeline, o.files, o.checks);
  addSamplingOptions(cmd, o.sampling);
}

void addWriterOptions(CLI::App& cmd, std::string& format, converter::EmitRequest& emit, const std::string& group) {
  std::vector<std::string> names;
  for (const converter::Emitter& e : converter::emitters()) names.emplace_back(e.name);
  cmd.add_option("--to", format, "output format (kerf convert --list shows them)")
      ->check(CLI::IsMember(names))
      ->group(group);
  cmd.add_option_function<int>(
         "--decimals",
         [&emit](const int& d) {
           emit.iso.decimals = d;
           emit.polar.decimals = d;
         },
         "iso, polar: digits after the decimal point (default: the machine's, 3)")
      ->check(CLI::Range(0, 6))
      ->group(group);
  cmd.add_flag("--compact", emit.threeB.compact, "3b, 4b: records without spaces (B9900B0B9900GXL1)")->group(group);
  addChoice<std::string>(cmd, "--end", emit.threeB.end, {{"dd", "DD"}, {"ff", "FF"}, {"none", ""}},
                         "3b, 4b: the end record: dd (default), ff or none")
      ->group(group);
  cmd.add_option("--max-points", emit.points.request.maxPoints,
                 "bp95d, points4: controller capacity: choose the step so the output fits")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000000}))
      ->group(group);
}

void addMeshOptions(CLI::App& cmd, MeshOptions& o, bool generators) {
  cmd.add_option("--mesh-tolerance", o.tolerance,
                 "largest distance of the mesh from the exact surface, mm (default 0.01)")
      ->check(CLI::Range(1e-5, 100.0))
      ->group("Mesh");
  if (generators)
    cmd.add_option("--generators", o.generators, "about this many wire lines along the cut (default 72; 0: none)")
        ->check(CLI::Range(std::size_t{0}, std::size_t{100000}))
        ->group("Mesh");
  if (generators)
    cmd.add_option("--show", o.show,
                   "more to draw: guides (the guides' paths and the wire extended to them: --guides, M100 P Q or "
                   "the profile's)")
        ->check(CLI::IsMember({"guides"}))
        ->group("Mesh");
}

// ---- 2. values given as text --------------------------------------------------------------------

bool sizeOption(const std::string& text, int& w, int& h) {
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &w, &h, &consumed) == 2 && consumed == static_cast<int>(text.size()) &&
      w >= 16 && h >= 16 && w <= 8192 && h <= 8192)
    return true;
  std::fprintf(stderr, "kerf: error: --size takes WIDTHxHEIGHT between 16 and 8192, not '%s'\n", text.c_str());
  return false;
}

std::string curveText(const InputOptions& input) {
  std::string text = input.curve.value_or("");
  if (input.range) text += "; t = " + *input.range;
  return text;
}

bool diagnosticPolicy(const CheckOptions& options, converter::DiagnosticPolicy& out, std::string& error) {
  using converter::Code;
  out = {};
  for (const std::string& w : options.codeOptions) {
    if (w == "error") {
      out.warningsAreErrors = true;
      continue;
    }
    const bool silence = w.starts_with("no-");
    const bool promote = w.starts_with("error=");
    const std::string id = silence ? w.substr(3) : promote ? w.substr(6) : std::string();
    const auto codes = converter::diagnosticCodes();
    const auto known = std::find_if(codes.begin(), codes.end(),
                                    [&](const converter::CodeInfo& c) { return converter::codeName(c.code) == id; });
    if ((!silence && !promote) || known == codes.end()) {
      error =
          "-W" + w + ": give -Wno-CODE, -Werror=CODE or -Werror, with a code that docs/diagnostics.md lists (K0604)";
      return false;
    }
    const Code code = known->code;
    if (silence && known->severity == converter::Severity::Error) {
      error = "-W" + w + ": " + id + " (" + std::string(known->name) + ") is an error, and errors cannot be silenced";
      return false;
    }
    (silence ? out.silenced : out.promoted).push_back(code);
  }
  return true;
}

std::optional<geometry::Vec2> pointOption(const std::string& text, const char* option, std::string& error) {
  double x = 0, y = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%n", &x, &y, &consumed) != 2 || consumed != static_cast<int>(text.size()) ||
      !(std::abs(x) <= 1e6) || !(std::abs(y) <= 1e6)) {
    error = std::string(option) + " takes X,Y in mm within 1e6 (for example 10,-5.5), not '" + text + "'";
    return std::nullopt;
  }
  return geometry::Vec2(x, y);
}

namespace {

/// LOWER,UPPER: two heights in mm within 1e6, the upper above the lower (--guides, --workpiece);
/// nothing, with error saying why, otherwise.
std::optional<std::array<double, 2>> heightsOption(const std::string& text, const char* option, std::string& error) {
  double lower = 0, upper = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%n", &lower, &upper, &consumed) != 2 ||
      consumed != static_cast<int>(text.size()) || !(std::abs(lower) <= 1e6) || !(std::abs(upper) <= 1e6) ||
      !(upper > lower)) {
    error = std::string(option) + " takes LOWER,UPPER in mm within 1e6, the upper above the lower (for example " +
            "-30,50), not '" + text + "'";
    return std::nullopt;
  }
  return std::array<double, 2>{lower, upper};
}

}  // namespace

// ---- 3. the pipeline's options ------------------------------------------------------------------

bool pipelineOptions(const CommonOptions& o, converter::PipelineOptions& out, std::string& error) {
  using namespace converter;
  out = o.pipeline;
  ReadOptions& r = out.read;
  if (o.input.curve && !r.format) r.format = InputFormat::Curve;
  if (o.input.machine) {
    if (findBuiltinMachine(*o.input.machine)) {
      r.machine = *o.input.machine;
    } else {
      std::error_code ec;
      if (!std::filesystem::exists(*o.input.machine, ec)) {
        std::string names;
        for (const std::string& n : builtinMachineNames()) names += (names.empty() ? "" : ", ") + n;
        error = "--machine '" + *o.input.machine + "' is neither a built-in profile (" + names + ") nor a file";
        return false;
      }
      std::optional<std::string> text = readTextFile(*o.input.machine, 1 << 20, error);
      if (!text) return false;
      r.machineFile = SourceText{*o.input.machine, std::move(*text)};
    }
  }
  // The files the options name: their texts, as the library takes them.
  auto read = [&](const std::optional<std::string>& file, std::size_t cap, std::optional<SourceText>& into) {
    if (!file) return true;
    std::optional<std::string> text = readTextFile(*file, cap, error);
    if (!text) return false;
    into = SourceText{*file, std::move(*text)};
    return true;
  };
  return read(o.files.offsets, 1 << 20, r.offsetsFile) &&
         read(o.files.drawing, o.input.maxInputMiB << 20, out.drawing) &&
         read(o.files.drawingUpper, o.input.maxInputMiB << 20, out.drawingUpper);
}

}  // namespace kerf::cli
