// The options of the kerf program, one group per concern, each declared once and added to the
// commands that take it; every default lives here, in the member initialisers.
#pragma once

#include "kerf/converter/formats/emit.h"
#include "kerf/converter/pipeline.h"
#include "kerf/geometry/tessellation.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

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

/// The files the reading and check options name (the program reads them; the library takes their
/// text). What the options mean is bound straight to the library's converter::PipelineOptions.
struct OptionFiles {
  std::optional<std::string> offsets;       ///< --offsets FILE: an offset table
  std::optional<std::string> drawing;       ///< --drawing FILE (DXF)
  std::optional<std::string> drawingUpper;  ///< --drawing-upper FILE (DXF)
};

/// Which diagnostics show and how (the program's concern, not the library's).
struct CheckOptions {
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

/// What every command that reads a program takes. Each option is declared once (options.cpp): the
/// ones the library takes are bound to `pipeline`, typed, with the library's defaults; the rest
/// (files to read, what the terminal shows) live in the groups beside it.
struct CommonOptions {
  InputOptions input;
  converter::PipelineOptions pipeline;  ///< reading, checks, the drawing: as the library takes them
  OptionFiles files;
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

/// The pipeline's options from the command line: `pipeline`, with the texts of the files the options
/// name (--machine FILE, --offsets, --drawing, --drawing-upper). False with a message when a file
/// cannot be read.
bool pipelineOptions(const CommonOptions& options, converter::PipelineOptions& out, std::string& error);

/// An option's X,Y in mm (`--start`, `--entry`, `--drawing-origin`), each within 1e6 mm; nothing,
/// with `error` saying why, otherwise.
std::optional<geometry::Vec2> pointOption(const std::string& text, const char* option, std::string& error);

/// Adds the options every writer's command takes, bound to the writer table's request: --to (into
/// `format`), --decimals, --compact, --end, --max-points.
void addWriterOptions(CLI::App& command, std::string& format, converter::EmitRequest& emit, const std::string& group);

// The two ways an option is bound to a library field that is not a plain number or string.

/// A choice among names, each meaning a value of the library's option: the text checked against
/// the names (so CLI11 says which it takes) and the value stored in `target`.
template <class T>
CLI::Option* addChoice(CLI::App& cmd, const std::string& name, T& target,
                       const std::vector<std::pair<std::string, T>>& choices, const std::string& help) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  return cmd
      .add_option_function<std::string>(
          name,
          [&target, choices](const std::string& text) {
            for (const auto& [n, value] : choices)
              if (n == text) target = value;
          },
          help)
      ->check(CLI::IsMember(names));
}

/// An option whose text the library takes parsed (X,Y; LOWER,UPPER): checked with `parse` (its
/// error said after the option's name), the value handed to `store`.
template <class V, class Store>
CLI::Option* addParsed(CLI::App& cmd, const std::string& name, const char* shape,
                       std::optional<V> (*parse)(const std::string&, const char*, std::string&), Store store,
                       const std::string& help) {
  const std::string flag = name.substr(name.rfind(',') == std::string::npos ? 0 : name.rfind(',') + 1);
  return cmd
      .add_option_function<std::string>(
          name,
          [flag, parse, store](const std::string& text) {
            std::string error;
            if (const std::optional<V> v = parse(text, flag.c_str(), error)) store(*v);
          },
          help)
      ->check(CLI::Validator(
          [flag, parse](std::string& text) {
            std::string error;
            if (parse(text, flag.c_str(), error)) return std::string();
            return error.starts_with(flag + " ") ? error.substr(flag.size() + 1) : error;
          },
          shape));
}

/// The machine profile names `--machine` accepts besides a file.
std::vector<std::string> builtinMachineNames();

}  // namespace kerf::cli
