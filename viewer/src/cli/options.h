// The options of the kerf program, one group per concern, each declared once and added to the
// commands that take it; every default lives here, in the member initialisers.
#pragma once

#include "kerf/converter/pipeline.h"
#include "kerf/geometry/tessellation.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kerf::cli {

/// The programs to read.
struct InputOptions {
  std::vector<std::string> files;        ///< "-" is standard input
  std::optional<std::string> filesFrom;  ///< --files-from: a list of files, folders or glob patterns ("-": stdin)
  std::optional<std::string> upper;      ///< --upper: two-file input
  std::optional<std::string> machine;    ///< --machine NAME or FILE
  /// --curve "x=…; y=…" and --t A:B: a curve (converter/formats/curve/read_curve.h) instead of a file; files then
  /// holds kCurveInput.
  std::optional<std::string> curve, range;
  bool fileRequired = true;  ///< false: the command runs without one (kerf convert --list)
  /// --max-input: the most bytes a program (and --upper) may hold, MiB; refused before it is read
  /// when its size is known, else once that many bytes have come (standard input, a pipe, a device).
  std::size_t maxInputMiB = 512;
};

/// The name a --curve input goes by (in files and in diagnostics).
inline constexpr const char* kCurveInput = "--curve";

/// The text a --curve input reads as: the statements of --curve, then "; t = " --t.
std::string curveText(const InputOptions& input);

/// What the program means (docs/machines.md: options first, then the profile, then the evidence).
struct ReadingOptions {
  std::string format = "auto";             ///< auto | iso | 3b
  std::optional<std::string> start;        ///< X,Y (3B)
  std::optional<std::string> polarX;       ///< diameter | radius (inside G12.1)
  std::optional<std::string> polarFrame;   ///< tool | table (the G12.1 frame)
  std::optional<std::string> dxfUnits;     ///< mm | in | file (DXF drawings)
  std::optional<double> chainTolerance;    ///< mm (DXF drawings)
  std::optional<double> curveTolerance;    ///< mm (curves, SPLINE, ELLIPSE as biarcs)
  std::optional<std::string> integerUnit;  ///< mm | um
  std::optional<std::string> arcCentre;    ///< incremental | reversed | absolute
  std::optional<double> offset;            ///< --offset, mm
  std::optional<std::string> offsets;      ///< --offsets FILE: an offset table
  std::optional<std::string> side;         ///< --side outside|inside (drawings)
  std::string dialect = "auto";
  std::optional<double> lowerZ, upperZ, thickness, programZ;
  std::optional<std::string> guides;     ///< LOWER_Z,UPPER_Z: the wire guides, mm (lower face at 0)
  std::optional<std::string> workpiece;  ///< Z0,Z1: the work's faces where the planes are the machine's
  std::optional<std::string> upperAxes;  ///< uv | uz
};

/// The checks' settings (defaults: the machine profile's).
struct CheckOptions {
  std::optional<double> maxTaper;            ///< degrees
  std::optional<double> uvRange;             ///< mm
  std::optional<double> speed;               ///< --speed, mm/min
  std::optional<std::string> drawing;        ///< --drawing FILE (DXF)
  double drawingTolerance = 0.005;           ///< --drawing-tolerance, mm
  std::optional<std::string> drawingOrigin;  ///< --drawing-origin X,Y
  std::string drawingLayer;                  ///< --drawing-layer NAME (empty: every layer)
  bool drawingAlign = false;                 ///< --align
  std::optional<std::string> drawingUpper;   ///< --drawing-upper FILE (DXF)
  std::string drawingUpperLayer;             ///< --drawing-upper-layer NAME
  std::size_t maxDiagnostics = 50;
  std::vector<std::string> codeOptions;  ///< -W values as given: no-K0604, error=K0650, error
  bool quiet = false;                    ///< --quiet: errors only
  std::string color = "auto";            ///< --color auto|always|never (auto: a terminal, and no NO_COLOR)
};

/// The -W values as a policy; false after saying what is wrong (an unknown code, an error silenced).
bool diagnosticPolicy(const CheckOptions& options, converter::DiagnosticPolicy& out, std::string& error);

struct SamplingOptions {
  static constexpr double kDefaultStep = 0.1;  ///< mm: the seed's finest interpolation step
  std::optional<double> step;
  std::optional<double> tolerance;
  [[nodiscard]] geometry::Sampling sampling() const;
};

/// How the part is meshed for a picture, the window or a mesh file.
struct MeshOptions {
  std::optional<double> tolerance;        ///< --mesh-tolerance, mm (default 0.01, render/scene.h)
  std::optional<std::size_t> generators;  ///< --generators: wire lines drawn along the cut
  std::vector<std::string> show;          ///< --show: more to draw (guides: the wire at its guides)
};

/// What every command that reads a program takes.
struct CommonOptions {
  InputOptions input;
  ReadingOptions reading;
  CheckOptions checks;
  SamplingOptions sampling;
};

/// Adds the input, reading, check and sampling groups to a command. manyFiles: the command takes
/// several programs (kerf check).
void addCommonOptions(CLI::App& command, CommonOptions& options, bool manyFiles);

/// Adds --mesh-tolerance (and --generators for the commands that draw lines) to a command.
void addMeshOptions(CLI::App& command, MeshOptions& options, bool generators);

/// WIDTHxHEIGHT between 16 and 8192; false after saying what is wrong.
bool sizeOption(const std::string& text, int& width, int& height);

/// The pipeline's options from the command line, reading --machine FILE when it names a file.
/// False with a message when a file cannot be read.
bool pipelineOptions(const CommonOptions& options, converter::PipelineOptions& out, std::string& error);

/// An option's X,Y in mm (`--start`, `--entry`, `--drawing-origin`), each within 1e6 mm; nothing,
/// with `error` saying why, otherwise.
std::optional<geometry::Vec2> pointOption(const std::string& text, const char* option, std::string& error);

/// The machine profile names `--machine` accepts besides a file.
std::vector<std::string> builtinMachineNames();

}  // namespace kerf::cli
