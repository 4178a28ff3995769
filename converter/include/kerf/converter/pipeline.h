// The one pipeline every command takes: read -> interpret -> check, with one options struct.
//
// check, explain, convert, render, view and export all call runPipeline with the options the
// user gave; so a picture, a mesh or a converted program carries exactly the findings `kerf check`
// reports with the same options. The pipeline reads no files and prints nothing: the caller gives
// it the texts and turns the result into output and an exit code.
//
//   text ──detect format──▶ [3B: readThreeB ──▶ Toolpath]
//   text ──parse──▶ Program ──machine profile (given, or detected from the evidence)──▶
//        ──integer unit, arc-centre convention (given, the profile's, or from the evidence)──▶
//        ──interpret──▶ Toolpath ──[two files: pair]──▶ checks ──▶ Findings
#pragma once

#include "kerf/converter/cam/cam.h"
#include "kerf/converter/check/checks.h"
#include "kerf/converter/check/drawing_check.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/formats/dxf/read_dxf.h"
#include "kerf/converter/formats/read.h"
#include "kerf/converter/interpret/interpreter.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/chain.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace kerf::converter {

/// A named text: a program, a machine profile.
struct SourceText {
  std::string name;
  std::string text;
};

/// What the program means. Every field is an override: nothing means "as the machine profile
/// says, or as the program's evidence shows" (docs/machines.md gives the order).
struct ReadOptions {
  std::optional<InputFormat> format;      ///< --format: nothing detects it from the content (read.h)
  std::optional<geometry::Vec2> start;    ///< --start X,Y: where a 3B program starts, mm
  std::optional<bool> polarXDiameter;     ///< --polar-x: X inside G12.1 (nothing: the profile's)
  std::optional<bool> polarFrameTable;    ///< --polar-frame: the G12.1 frame (nothing: the profile's)
  std::optional<std::string> machine;     ///< --machine NAME: a built-in profile
  std::optional<SourceText> machineFile;  ///< --machine FILE: a profile's text
  std::optional<SourceText> offsetsFile;  ///< --offsets FILE: an offset table's text (offset_table.h)
  std::optional<IntegerUnit> integerUnit;
  std::optional<ArcCentreMode> arcCentre;
  std::optional<Dialect> dialect;
  std::optional<double> lowerZ, upperZ, thickness, programZ;  ///< mm
  std::optional<std::array<double, 2>> guides;                ///< --guides LOWER_Z,UPPER_Z, mm (lower face at 0)
  /// --workpiece Z0,Z1: the work's faces, mm, where the program's planes are the machine's (a foam
  /// cutter's carriages): the part is cut between them (interpret/workpiece.h).
  std::optional<std::array<double, 2>> workpiece;
  std::optional<double> wireOffset;  ///< --offset, mm
  /// --side: a drawing's closed contours get the wire path at --offset on this side (cam.h).
  std::optional<WireSide> side;
  std::optional<bool> upperAxesUZ;             ///< --upper-axes uz
  std::optional<double> dxfUnit;               ///< --dxf-units: mm per drawing unit; 0 follows $INSUNITS (read_dxf.h)
  double chainTolerance = 0.001;               ///< --chain-tolerance: drawing ends this close are joined, mm
  double curveTolerance = 0.001;               ///< drawing curves (SPLINE, ELLIPSE) as biarcs within this, mm
  std::size_t maxExecutedBlocks = 20'000'000;  ///< the interpreter's limits (InterpreterOptions)
  std::size_t maxMoves = 10'000'000;
};

/// The checks' settings; nothing: the machine profile's value.
struct CheckSettings {
  std::optional<double> maxTaperDegrees;     ///< --max-taper
  std::optional<double> uvRange;             ///< --uv-range, mm
  std::optional<std::size_t> sectionBudget;  ///< CheckOptions::sectionBudget (the fuzz target lowers it)
  std::optional<int> surfaceLevels;          ///< CheckOptions::surfaceLevels (the fuzz target lowers it)
  std::optional<double> speed;               ///< --speed: mm/min of every cut, for the time estimate
};

struct PipelineOptions {
  ReadOptions read;
  CheckSettings check;
  /// Set: Pipeline::summary at this sampling, made after the checks (it reads their measures).
  std::optional<geometry::Sampling> summarize;
  /// Keep how each arc's centre was written (Toolpath::centreWords; `kerf explain` shows it). The
  /// 3B and mill-turn readers always keep it.
  bool centreWords = false;
  /// --drawing: the DXF the program should cut, compared after the checks (check/drawing_check.h).
  std::optional<SourceText> drawing;
  /// --drawing-upper: a taper program's upper plane against this DXF (with --drawing-upper-layer
  /// and no file: the upper plane against that layer of --drawing).
  std::optional<SourceText> drawingUpper;
  DrawingCheckOptions drawingCheck;
};

/// Everything a command needs after reading and checking a program. The sources live as long as
/// the result (diagnostics and spans point into them).
struct Pipeline {
  std::unique_ptr<SourceFile> source;
  std::unique_ptr<SourceFile> upperSource;    ///< two-file input
  std::unique_ptr<SourceFile> machineSource;  ///< --machine FILE
  std::unique_ptr<SourceFile> offsetsSource;  ///< --offsets FILE
  InputFormat format = InputFormat::Iso;      ///< the format the program was read as
  std::optional<DrawingResult> drawing;       ///< DXF only: the toolpath then walks its contours
  /// DXF with --offset and --side: per contour (same index), the wire path (empty for open ones);
  /// the toolpath then walks the wire paths.
  std::vector<ContourWire> wires;
  Toolpath toolpath;
  MachineProfile machine;              ///< the profile in force
  bool machineDetected = false;        ///< chosen from the evidence, not given
  SurfaceMeasures measures;            ///< per move, for a taper program whose heights are known
  Structure structure;                 ///< contours and passes, with the time estimate (a program, not a drawing)
  CheckOptions checkOptions;           ///< the settings the checks ran with
  Diagnostics diags{kAllDiagnostics};  ///< every diagnostic, sorted by position
  /// What was read: set whenever `read` is, if PipelineOptions::summarize asked for it.
  std::optional<Summary> summary;
  /// false: nothing was read (the machine profile file or the --offsets table is wrong); diags says why.
  bool read = false;
  std::unique_ptr<SourceFile> drawingSource;         ///< --drawing
  std::optional<DrawingComparison> comparison;       ///< the program against --drawing
  std::unique_ptr<SourceFile> drawingUpperSource;    ///< --drawing-upper
  std::optional<DrawingComparison> comparisonUpper;  ///< the upper plane against its drawing
};

/// The geometry the wire path was made from, where the two differ: the drawing of --drawing, placed
/// as compared; a drawing's closed contours under --offset (the toolpath is their wire path); a
/// program's contour as written where G41/G42 was applied (each programmed move once). Empty
/// otherwise. Pictures draw it beside the path.
std::vector<geometry::Segment> referenceGeometry(const Pipeline& pipeline);

/// Reads, interprets and checks `input` (with `upper` as the upper contour's program: two-file
/// input). Never throws on bad input: problems are diagnostics.
Pipeline runPipeline(SourceText input, const PipelineOptions& options, std::optional<SourceText> upper = {});

}  // namespace kerf::converter
