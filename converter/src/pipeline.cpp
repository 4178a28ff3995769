// The one pipeline every command runs (pipeline.h).
// Sections: 1. conventions from the evidence  2. the pipeline
#include "kerf/converter/pipeline.h"

#include "kerf/converter/formats/3b/read_3b.h"
#include "kerf/converter/formats/curve/read_curve.h"
#include "kerf/converter/interpret/analysis.h"
#include "kerf/converter/interpret/mill_turn.h"
#include "kerf/converter/interpret/workpiece.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/structure/cutting_time.h"

#include <cstdio>
#include <optional>
#include <set>

namespace kerf::converter {
namespace {

/// A value in a note on the evidence: up to 15 significant digits.
std::string evidenceNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

// ---- 1. conventions from the evidence --------------------------------------------------------

/// Integers without a decimal point: micrometres when no length word has a point and the largest
/// is above the profile's threshold (docs/machines.md).
std::optional<std::string> integerEvidence(const Program& p, const MachineProfile& m) {
  if (p.anyDecimalPoint || p.integerLengthWords == 0 || p.largestInteger <= m.integerThreshold) return std::nullopt;
  return "µm integers: " + std::to_string(p.integerLengthWords) + " coordinates without a decimal point, largest " +
         evidenceNumber(p.largestInteger);
}

/// "incremental", "reversed (start minus centre)", "absolute": the convention named in a note.
std::string centreAdjective(ArcCentreMode m) {
  return m == ArcCentreMode::Reversed ? std::string(arcCentreName(m)) + " (" + arcCentreMeaning(m) + ")"
                                      : std::string(arcCentreName(m));
}

/// Another I J convention, when the evidence decides for it: some arc closes that way only, none
/// closes only the way in force, and every arc that closes at all closes that way. An arc that
/// closes no way is no evidence (it is an error under any convention, reported at its line); arcs
/// that close several ways are none either. Otherwise the convention in force (the profile's
/// default) holds.
std::optional<ArcCentreMode> betterCentre(const ArcCentreTally& t, ArcCentreMode used) {
  const auto u = static_cast<int>(used);
  if (t.arcs == 0 || t.only[u] > 0 || t.closes[u] == t.arcs) return std::nullopt;
  for (ArcCentreMode m : {ArcCentreMode::Incremental, ArcCentreMode::Absolute, ArcCentreMode::Reversed}) {
    const auto k = static_cast<int>(m);
    if (m != used && t.only[k] > 0 && t.closes[k] + t.closeNoWay == t.arcs) return m;
  }
  return std::nullopt;
}

std::string centreEvidence(const ArcCentreTally& t, ArcCentreMode m) {
  const std::size_t closes = t.closes[static_cast<int>(m)];
  std::size_t others = 0;
  for (int k = 0; k < 3; ++k)
    if (k != static_cast<int>(m)) others = std::max(others, t.closes[k]);
  return centreAdjective(m) + " centres: " + std::to_string(closes) + " of " + std::to_string(t.arcs) +
         (t.arcs == 1 ? " arc closes" : " arcs close") + (others == 0 ? " only that way" : " that way");
}

}  // namespace

// ---- 2. the pipeline -----------------------------------------------------------------------

namespace {

/// The summary, when the caller asked for one.
void summarizeInto(Pipeline& out, const PipelineOptions& options) {
  if (!options.summarize) return;
  out.summary = summarize(out.toolpath, *options.summarize, &out.measures);
  out.summary->structure = out.structure;
  out.summary->comparison = out.comparison;
  out.summary->comparisonUpper = out.comparisonUpper;
}

/// How a DXF is read under the options: its unit, its curves' tolerance, its budget.
DxfOptions dxfOptionsOf(const ReadOptions& ro) {
  DxfOptions o;
  if (ro.dxfUnit) o.unitToMm = *ro.dxfUnit;
  o.curveTolerance = ro.curveTolerance;
  o.maxElements = ro.maxMoves;
  return o;
}

/// One plane's drawing: the DXF read (in mm, its own findings at its lines), the layer asked for
/// kept, and the part edge on that plane held against it. Nothing when there is nothing to compare.
std::optional<DrawingComparison> compareOnePlane(Pipeline& out, const PipelineOptions& options,
                                                 const SourceFile& source, const std::string& layer, bool upper) {
  const Drawing drawing = readDxf(source, dxfOptionsOf(options.read), out.diags);
  if (!drawing.ok) return std::nullopt;
  std::vector<DrawnElement> drawn;
  drawn.reserve(drawing.elements.size());
  for (const DrawingElement& e : drawing.elements)
    if (layer.empty() || e.layer == layer) drawn.push_back({e.segment, e.entity, e.where, e.span});
  if (drawn.empty()) {
    std::set<std::string> layers;
    for (const DrawingElement& e : drawing.elements) layers.insert(e.layer);
    std::string names;
    for (const std::string& l : layers) names += (names.empty() ? "" : ", ") + (l.empty() ? "\"\"" : l);
    out.diags.error(Code::DrawingEmpty, &source, SourceSpan{0, 0},
                    (layer.empty() ? std::string("the drawing") : "the drawing's layer " + layer) +
                        " holds no line, arc or curve to compare the program with",
                    names.empty() ? std::string() : "its layers with elements: " + names);
    return std::nullopt;
  }
  DrawingCheckOptions o = options.drawingCheck;
  o.wireOffset = options.read.wireOffset;
  if (options.read.side) o.wireOutside = *options.read.side == WireSide::Outside;
  o.upperPlane = upper;
  DrawingComparison c = compareWithDrawing(out.toolpath, out.structure, drawn, o, out.source.get(), &source, out.diags);
  c.upper = upper;
  return c;
}

/// --drawing, and for a taper program --drawing-upper or --drawing-upper-layer: each plane's part
/// edge against its drawing.
void compareDrawing(Pipeline& out, const PipelineOptions& options) {
  if (options.drawing) {
    out.drawingSource = std::make_unique<SourceFile>(options.drawing->name, options.drawing->text);
    out.comparison = compareOnePlane(out, options, *out.drawingSource, options.drawingCheck.layer, false);
  }
  if (!options.drawingUpper && options.drawingCheck.upperLayer.empty()) return;
  const SourceFile* upper = out.drawingSource.get();
  if (options.drawingUpper) {
    out.drawingUpperSource = std::make_unique<SourceFile>(options.drawingUpper->name, options.drawingUpper->text);
    upper = out.drawingUpperSource.get();
  }
  if (!out.toolpath.isTaper() || upper == nullptr) {
    out.diags.error(Code::OptionDoesNotFit, upper ? upper : out.source.get(), SourceSpan{0, 0},
                    upper ? "the upper plane's drawing needs a taper program: this program has no upper contour"
                          : "--drawing-upper-layer names a layer of --drawing, and no --drawing is given");
    return;
  }
  out.comparisonUpper = compareOnePlane(out, options, *upper, options.drawingCheck.upperLayer, true);
}

/// --workpiece: the part between the work's faces, the program's planes the machine's. Its sections
/// are within the curve tolerance (0.001 mm unless --curve-tolerance says). False when refused.
bool cutWorkpiece(Pipeline& out, const PipelineOptions& options) {
  const std::optional<std::array<double, 2>>& w = options.read.workpiece;
  if (!w) return true;
  return cutBetweenFaces(out.toolpath, (*w)[0], (*w)[1], options.read.curveTolerance, options.read.maxMoves,
                         out.source.get(), out.diags);
}

/// The checks, with the machine's limits unless the user gave others, then the summary (it reads
/// the measures the checks computed).
void runChecks(Pipeline& out, const PipelineOptions& options) {
  out.checkOptions.maxTaperDegrees = options.check.maxTaperDegrees.value_or(out.machine.maxTaperDegrees);
  out.checkOptions.uvRange = options.check.uvRange ? options.check.uvRange : out.machine.uvRange;
  if (options.check.sectionBudget) out.checkOptions.sectionBudget = *options.check.sectionBudget;
  if (options.check.surfaceLevels) out.checkOptions.surfaceLevels = *options.check.surfaceLevels;
  out.structure = findStructure(out.toolpath, out.checkOptions.tolerance);
  estimateTime(out.toolpath, speedModel(out.machine, out.toolpath, options.check.speed), out.structure);
  if (out.toolpath.blocks > 0) {
    out.measures = measureSurface(out.toolpath);
    checkToolpath(out.toolpath, out.source.get(), out.checkOptions, out.diags, &out.measures, &out.structure);
  }
  compareDrawing(out, options);
  summarizeInto(out, options);
  out.diags.sortByPosition();
}

/// A drawing that yields nothing to cut says so, whatever the reason (issue 41): what it holds
/// instead, counted (K0606 at 1:1).
void reportEmptyDrawing(Pipeline& out, const Drawing& drawing) {
  std::string skipped;
  for (const auto& [type, n] : drawing.skipped)
    skipped += (skipped.empty() ? "" : ", ") + std::to_string(n) + " " + type;
  out.diags.error(Code::NothingCut, out.source.get(), SourceSpan{0, 0},
                  "the drawing holds no line, arc or curve Kerf can cut: nothing to cut" +
                      (skipped.empty() ? std::string() : " (it holds " + skipped + ")"));
}

/// A drawing: read, chained into contours, and walked as a toolpath (drawingToolpath: a rapid to
/// each contour's start, then its elements or its wire path) so that summary, explain, pictures and
/// export show it. The wire-path
/// checks are not run: a drawing is not a program (kerf cam makes one from it).
void readDrawingPipeline(Pipeline& out, const PipelineOptions& options) {
  const ReadOptions& ro = options.read;
  DrawingResult result;
  if (out.format == InputFormat::Curve) {
    CurveOptions o;
    o.tolerance = ro.curveTolerance;
    o.maxSpans = ro.maxMoves;
    result.drawing = readCurve(*out.source, o, out.diags);
  } else {
    result.drawing = readDxf(*out.source, dxfOptionsOf(ro), out.diags);
  }
  if (result.drawing.elements.empty() && !out.diags.hasErrors()) reportEmptyDrawing(out, result.drawing);
  std::vector<geometry::Segment> segments;
  segments.reserve(result.drawing.elements.size());
  for (const DrawingElement& e : result.drawing.elements) segments.push_back(e.segment);
  geometry::ChainOptions co;
  co.tolerance = ro.chainTolerance;
  result.contours = geometry::chainSegments(segments, co);
  result.depth = geometry::nestingDepths(result.contours);
  // With --offset and --side: the wire path of every closed contour (holes inside others on the
  // other side), and the drawing as a toolpath in the order kerf cam cuts it (cam.h).
  const bool wired = ro.wireOffset && ro.side && *ro.wireOffset > 0;
  if (wired) out.wires = drawingWires(result, *ro.wireOffset, *ro.side, out.source.get(), out.diags);
  out.toolpath = drawingToolpath(result, wired ? &out.wires : nullptr);
  Toolpath& path = out.toolpath;
  path.format = out.format;
  path.reading.machine = out.machine.name;
  path.blocks = result.drawing.elements.size();
  for (const geometry::Chain& c : result.contours) {
    if (c.closed) continue;
    const DrawingElement& last = result.drawing.elements[c.elements.back()];
    const geometry::Vec2 a = c.path.front().start, b = c.path.back().end;
    out.diags.warning(Code::ContourOpen, out.source.get(), last.span.length ? last.span : SourceSpan::wholeFile(),
                      "a chain of " + std::to_string(c.elements.size()) + " element" +
                          (c.elements.size() == 1 ? "" : "s") + " does not close: its ends (" + formatFixed(a.x(), 3) +
                          ", " + formatFixed(a.y(), 3) + ") and (" + formatFixed(b.x(), 3) + ", " +
                          formatFixed(b.y(), 3) + ") are " + formatFixed(c.gap, 4) + " mm apart",
                      "ends closer than --chain-tolerance (" + formatFixed(ro.chainTolerance, 4) +
                          " mm) are joined; a contour to cut must close");
  }
  out.drawing = std::move(result);
  out.structure = findStructure(path, out.checkOptions.tolerance);
  summarizeInto(out, options);
}

/// The profile the options name: a profile file's text (read here, its errors into out.diags) or a
/// built-in name. profile is null when none is named: the program's evidence then picks one.
/// failed is set when the file cannot be read or the name is not built in (the error is in
/// out.diags).
struct GivenMachine {
  const MachineProfile* profile = nullptr;
  bool failed = false;
};
GivenMachine givenMachine(Pipeline& out, const ReadOptions& ro) {
  if (ro.machineFile) {
    out.machineSource = std::make_unique<SourceFile>(ro.machineFile->name, ro.machineFile->text);
    std::optional<MachineProfile> parsed = parseMachineProfile(*out.machineSource, out.diags);
    if (!parsed) return {nullptr, true};
    out.machine = std::move(*parsed);
    return {&out.machine, false};
  }
  if (ro.machine) {
    const MachineProfile* builtin = findBuiltinMachine(*ro.machine);
    if (!builtin) {
      out.diags.error(Code::MachineProfileError, nullptr, SourceSpan::wholeFile(),
                      "there is no built-in machine profile named '" + *ro.machine + "'",
                      "kerf machines lists them; --machine also takes a profile file");
      return {nullptr, true};
    }
    out.machine = *builtin;
    return {builtin, false};
  }
  return {};
}

/// The interpreter's conventions from the options, else the profile, else the program's own
/// evidence; an integer unit taken from the program says why in evidence. An upper program of a
/// two-file taper pair (hasUpper) is read in the plain dialect.
InterpreterOptions interpreterOptions(const MachineProfile& machine, const PipelineOptions& options,
                                      const OffsetTable& offsets, const Program& program, bool hasUpper,
                                      std::vector<std::string>& evidence) {
  const ReadOptions& ro = options.read;
  InterpreterOptions io;
  io.machine = &machine;
  io.dialect = hasUpper ? Dialect::Plain : ro.dialect;
  io.lowerZ = ro.lowerZ;
  io.upperZ = ro.upperZ;
  io.thickness = ro.thickness;
  io.programZ = ro.programZ;
  io.guides = ro.guides;
  io.wireOffset = ro.wireOffset;
  io.offsets = offsets;
  io.offsets.insert(machine.offsets.begin(), machine.offsets.end());  // the file's first: insert keeps them
  io.maxExecutedBlocks = ro.maxExecutedBlocks;
  io.maxMoves = ro.maxMoves;
  io.recordCentreWords = options.centreWords;
  if (ro.integerUnit) {
    io.integerUnit = *ro.integerUnit;
  } else if (machine.integerUnit) {
    io.integerUnit = *machine.integerUnit;
  } else if (auto e = integerEvidence(program, machine)) {
    io.integerUnit = IntegerUnit::Micrometre;
    evidence.push_back(*e);
  }
  io.arcCentre = ro.arcCentre ? *ro.arcCentre : machine.arcCentre.value_or(ArcCentreMode::Incremental);
  return io;
}

/// The program interpreted into a toolpath, its diagnostics into diags; a mill-turn face program
/// (mill_turn.h, docs/polar.md) with the face's words. Unless the options or the
/// profile fix the I J convention, the program is read again with the other one when its arcs'
/// centres say so (io.arcCentre is then that one); evidence says which convention and why.
Interpretation interpretForMachine(const Program& program, const MachineProfile& machine, const ReadOptions& ro,
                                   InterpreterOptions& io, Diagnostics& diags, std::vector<std::string>& evidence) {
  const KnownCode* cCode = machine.find("C");
  const bool cIsRotary = !cCode || (cCode->effect != CodeEffect::Harmless &&
                                    cCode->effect != CodeEffect::Condition);  // Sodick: C is a condition
  const bool millTurn = isMillTurnProgram(program) || (cIsRotary && hasRotaryMoves(program));
  if (millTurn) {
    MillTurnOptions mt;
    mt.polarXDiameter = ro.polarXDiameter.value_or(!machine.polarXRadius);
    mt.polarCDiameter = machine.polarCDiameter;
    mt.polarFrameTable = ro.polarFrameTable.value_or(machine.polarFrameTable);
    io.millTurn = mt;
  }
  Interpretation in = interpretProgram(program, io, diags);
  const bool centreFixed = ro.arcCentre || machine.arcCentre;
  if (!centreFixed) {
    if (const std::optional<ArcCentreMode> better = betterCentre(in.arcs, io.arcCentre)) {
      io.arcCentre = *better;
      diags = Diagnostics(kAllDiagnostics);
      in = interpretProgram(program, io, diags);
      evidence.push_back(centreEvidence(in.arcs, *better));
    }
  } else if (machine.arcCentre && !ro.arcCentre && in.arcs.arcs > 0 &&
             *machine.arcCentre != ArcCentreMode::Incremental) {
    evidence.push_back(centreEvidence(in.arcs, *machine.arcCentre));
  }
  return in;
}

/// The note that says for which machine, and with which conventions, the program was read, and
/// why: up to four pieces of the detection's evidence and what the conventions were taken from.
/// None when the generic profile was taken with nothing to say.
void noteHowRead(Pipeline& out, const MachineDetection& detection, const std::vector<std::string>& evidence) {
  const MachineProfile& machine = out.machine;
  const bool namedMachine = out.machineDetected && machine.name != "generic";
  if (!namedMachine && evidence.empty()) return;
  std::string message;
  SourceSpan span = SourceSpan::wholeFile();
  if (namedMachine) {
    message = "read for the " + machine.name + " machine, from ";
    for (std::size_t k = 0; k < detection.evidence.size() && k < 4; ++k)
      message += std::string(k ? ", " : "") + detection.evidence[k].what;
    if (detection.evidence.size() > 4) message += " and " + std::to_string(detection.evidence.size() - 4) + " more";
    span = detection.evidence.front().span;
  } else {
    message = "read with the " + machine.name + " profile";
  }
  for (const std::string& e : evidence) message += "; " + e;
  out.diags.note(
      Code::MachineDetected, out.source.get(), span, message,
      "override with --machine NAME or FILE, --integer-unit, --arc-centre (kerf machines lists the profiles)");
}

/// An --offsets table, when the options name one: its errors (in out.diags) say why nothing is
/// read, and nothing is returned. An empty table when none is named.
std::optional<OffsetTable> readOffsetsOption(Pipeline& out, const ReadOptions& ro) {
  if (!ro.offsetsFile) return OffsetTable{};
  out.offsetsSource = std::make_unique<SourceFile>(ro.offsetsFile->name, ro.offsetsFile->text);
  return readOffsetTable(*out.offsetsSource, out.diags);
}

/// The conventions an ISO lower program was read with, for its upper program.
struct LowerReading {
  const InterpreterOptions& io;
  const ParseOptions& parse;
};

/// The upper program of a two-file taper pair, whatever the lower one's format: 3B read as 3B; ISO
/// parsed and interpreted with the lower program's rules and conventions when the lower one is ISO
/// (lower), else with the options and the machine profile exactly as a lower ISO program would be
/// (integer unit, I J convention, offsets, limits: issue 55). Its source is kept in out and its
/// diagnostics go to out.diags.
Toolpath readUpperProgram(Pipeline& out, SourceText upper, const PipelineOptions& options, const OffsetTable& offsets,
                          const LowerReading* lower) {
  out.upperSource = std::make_unique<SourceFile>(std::move(upper.name), std::move(upper.text));
  Diagnostics upperDiags(kAllDiagnostics);
  Toolpath upperPath;
  if (detectFormat(out.upperSource->text()).format == InputFormat::ThreeB) {
    ThreeBOptions tb;
    if (options.read.start) tb.start = *options.read.start;
    upperPath = readThreeB(*out.upperSource, tb, upperDiags);
  } else if (lower) {
    const Program upperProgram = parseProgram(*out.upperSource, upperDiags, lower->parse);
    upperPath = interpret(upperProgram, lower->io, upperDiags);
  } else {
    MachineReading reading = readForMachine(*out.upperSource, &out.machine, options.read.upperAxesUZ);
    upperDiags.append(std::move(reading.diags));
    std::vector<std::string> evidence;  // the lower program's note says how the pair was read
    InterpreterOptions io = interpreterOptions(out.machine, options, offsets, reading.program, true, evidence);
    upperPath = interpretForMachine(reading.program, out.machine, options.read, io, upperDiags, evidence).toolpath;
  }
  out.diags.append(std::move(upperDiags));
  return upperPath;
}

/// 3B code (read_3b.h): its planes from the options alone (3B has no heights), and a two-file
/// pair's upper program.
void readThreeBPipeline(Pipeline& out, const PipelineOptions& options, std::optional<SourceText> upper) {
  const ReadOptions& ro = options.read;
  Toolpath upperPath;
  if (upper) {
    const std::optional<OffsetTable> offsets = readOffsetsOption(out, ro);
    if (!offsets) return;
    upperPath = readUpperProgram(out, std::move(*upper), options, *offsets, nullptr);
  }
  // 3B code says no position: it starts at --start, else where its upper program starts (the same
  // part's other plane, in that program's frame), else at the origin.
  ThreeBOptions tb;
  if (ro.start)
    tb.start = *ro.start;
  else if (upper)
    tb.start = upperPath.start;
  out.toolpath = readThreeB(*out.source, tb, out.diags);
  PlaneHeights& h = out.toolpath.heights;  // 3B has no heights: only the options give them
  h.planes.lower = ro.lowerZ.value_or(0.0);
  h.programZ = ro.programZ.value_or(h.planes.lower);
  const std::optional<double> upperZ = ro.upperZ      ? ro.upperZ
                                       : ro.thickness ? std::optional<double>(h.planes.lower + *ro.thickness)
                                       : out.machine.thickness
                                           ? std::optional<double>(h.planes.lower + *out.machine.thickness)
                                           : std::nullopt;
  if (upperZ && *upperZ > h.planes.lower) {
    h.planes.upper = *upperZ;
    h.known = true;
    h.source = "the options";
  }
  if (upper) pairUpper(out.toolpath, upperPath, out.source.get(), out.upperSource.get(), out.diags);
  cutWorkpiece(out, options);
  runChecks(out, options);
}

}  // namespace

Pipeline runPipeline(SourceText input, const PipelineOptions& options, std::optional<SourceText> upper) {
  Pipeline out;
  out.source = std::make_unique<SourceFile>(std::move(input.name), std::move(input.text));
  const ReadOptions& ro = options.read;

  // 1. The machine profile the options name, if any; a drawing or 3B code has its own route.
  const GivenMachine given = givenMachine(out, ro);
  if (given.failed) return out;
  out.read = true;
  out.format = ro.format ? *ro.format : detectFormat(out.source->text()).format;
  if (out.format == InputFormat::Dxf || out.format == InputFormat::Curve) {
    if (!given.profile) out.machine = *findBuiltinMachine("generic");
    readDrawingPipeline(out, options);
    return out;
  }
  if (out.format == InputFormat::ThreeB) {
    if (!given.profile) out.machine = *findBuiltinMachine("generic");
    readThreeBPipeline(out, options, std::move(upper));
    return out;
  }

  // An --offsets table: its errors say why nothing is read.
  const std::optional<OffsetTable> offsets = readOffsetsOption(out, ro);
  if (!offsets) {
    out.read = false;
    return out;
  }

  // 2. The program parsed with its profile's rules (detected from the program when none is named).
  // The parse tree lives only while the program is interpreted: nothing after needs it (the source
  // and the toolpath say everything), and the checks then run without its memory.
  MachineReading reading = readForMachine(*out.source, given.profile, ro.upperAxesUZ);
  Program program = std::move(reading.program);
  if (!given.profile) {
    out.machine = *reading.machine;
    out.machineDetected = true;
  }

  // 3. The conventions, then the program interpreted with them.
  std::vector<std::string> evidence;
  InterpreterOptions io = interpreterOptions(out.machine, options, *offsets, program, upper.has_value(), evidence);
  Diagnostics interpretDiags(kAllDiagnostics);
  Interpretation in = interpretForMachine(program, out.machine, ro, io, interpretDiags, evidence);
  out.toolpath = std::move(in.toolpath);
  out.diags.append(std::move(reading.diags));
  noteHowRead(out, reading.detection, evidence);
  out.diags.append(std::move(interpretDiags));
  if (upper) {
    const LowerReading lower{io, reading.parse};
    const Toolpath upperPath = readUpperProgram(out, std::move(*upper), options, *offsets, &lower);
    pairUpper(out.toolpath, upperPath, out.source.get(), out.upperSource.get(), out.diags);
  }

  if (program.blocks.empty() && !out.diags.hasErrors())  // with errors, those say why nothing was read
    out.diags.error(Code::NothingCut, out.source.get(), SourceSpan{0, 0},  // where a program would start
                    "the file holds no program (no block of words): nothing to cut");
  program = Program{};  // the checks need the toolpath alone

  // 4. The part between the work's faces (--workpiece), the checks and the summary.
  cutWorkpiece(out, options);
  runChecks(out, options);
  return out;
}

std::vector<geometry::Segment> referenceGeometry(const Pipeline& p) {
  if (p.comparison) return p.comparison->drawn;  // --drawing: the drawing the program should cut
  std::vector<geometry::Segment> out;
  if (p.drawing && !p.wires.empty()) {
    for (std::size_t c = 0; c < p.drawing->contours.size() && c < p.wires.size(); ++c)
      if (p.drawing->contours[c].closed)
        out.insert(out.end(), p.drawing->contours[c].path.begin(), p.drawing->contours[c].path.end());
    return out;
  }
  const Toolpath& tp = p.toolpath;
  for (std::size_t i = 0; i < tp.programmed.size() && i < tp.offsetRole.size(); ++i) {
    if (tp.offsetRole[i] == OffsetRole::Corner || !tp.moves[i].isCut()) continue;
    const geometry::Segment& s = tp.programmed[i];
    // One programmed move split over several applied pieces is drawn once.
    if (!out.empty() && out.back().start == s.start && out.back().end == s.end) continue;
    out.push_back(s);
  }
  return out;
}

}  // namespace kerf::converter
