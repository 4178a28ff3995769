// The report of check and explain, text and JSON (report.h).
// Sections: 1. numbers  2. check  3. explain
#include "kerf/converter/report/report.h"

#include "figures.h"

#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/formats/read.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/construction.h"
#include "kerf/geometry/arc.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace kerf::converter {
namespace {

using geometry::Vec2;
using nlohmann::json;

// ---- 1. numbers --------------------------------------------------------------------------------

using figures::deg;
using figures::mm;
std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}
std::string plural(std::size_t n, const char* word) {
  const std::string_view w(word);
  const char* ending = w.ends_with("ch") || w.ends_with("ss") ? "es" : "s";
  return std::to_string(n) + " " + word + (n == 1 ? "" : ending);
}
json vec(const Vec2& p) { return json::array({p.x(), p.y()}); }

/// The contours and passes (docs/passes.md): what the text's pass table says, for every program.
json structureObject(const Structure& st) {
  json contours = json::array();
  for (const Contour& c : st.contours) {
    json passes = json::array();
    for (const Pass& p : c.passes) {
      const int kept = keptSide(p);
      json pj = {{"first_line", p.firstLine},
                 {"last_line", p.lastLine},
                 {"first_move", p.first},
                 {"end_move", p.end},
                 {"side", p.side == WireOffset::Left    ? "G41"
                          : p.side == WireOffset::Right ? "G42"
                                                        : "none"},
                 {"register", p.offsetRegister.empty() ? json(nullptr) : json(p.offsetRegister)},
                 {"offset_mm", p.offset ? json(*p.offset) : json(nullptr)},
                 {"direction", directionName(p.direction)},
                 {"kept", kept > 0   ? "inside"
                          : kept < 0 ? "outside"
                                     : "unknown"},
                 {"closes", p.closes},
                 {"cut_off", p.cutOff},
                 {"gap_mm", p.gap},
                 {"length_mm", p.length},
                 {"contour_length_mm", p.alongLength},
                 {"condition", p.condition.empty() ? json(nullptr) : json(p.condition)},
                 {"minutes", p.minutes ? json(*p.minutes) : json(nullptr)},
                 {"speed_mm_per_min", p.minutes && *p.minutes > 0 ? json(p.length / *p.minutes) : json(nullptr)}};
      passes.push_back(std::move(pj));
    }
    contours.push_back({{"start_hole", vec(c.startHole)}, {"passes", std::move(passes)}});
  }
  const TimeEstimate& t = st.time;
  json time = {{"total_min", t.total()},
               {"cutting_min", t.cutting},
               {"rapids_min", t.rapids},
               {"threading_min", t.threading},
               {"complete", t.missing.empty()},
               {"passes_timed", t.passesTimed},
               {"missing", t.missing.empty() ? json(nullptr) : json(t.missing)},
               {"model", t.model}};
  return {{"contours", std::move(contours)}, {"time", std::move(time)}};
}

/// JSON output's stated precision (docs/formats.md): lengths and angles to 10 decimals (0.1 nm,
/// 1e-10 degree), so arithmetic noise (3.55e-15 for 0, 90.00000000000001 for 90) does not reach
/// the report; a relative error keeps 4 significant digits, as the text shows it.
void roundNumbers(json& j, bool relative = false) {
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v)) return;
    double r = v;
    if (relative) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3e", v);
      r = std::strtod(buf, nullptr);
    } else {
      if (std::abs(v) < 1e5) r = std::round(v * 1e10) / 1e10;  // larger doubles hold fewer decimals anyway
    }
    j = r == 0.0 ? 0.0 : r;  // no -0
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) roundNumbers(it.value(), it.key().ends_with("relative_error"));
  } else if (j.is_array()) {
    for (json& e : j) roundNumbers(e, relative);
  }
}

std::string samplingText(const geometry::Sampling& s) {
  // Six decimals, or the value in scientific notation when those would show it as 0.000000.
  const std::string value = s.value >= 1e-6 ? formatFixed(s.value, 6) : sci(s.value);
  return s.mode == geometry::SamplingMode::Step ? "step k = " + value + " mm" : "tolerance " + value + " mm";
}
json samplingJson(const geometry::Sampling& s) {
  return {{"mode", s.mode == geometry::SamplingMode::Step ? "step" : "tolerance"}, {"value", s.value}};
}

const char* kindName(MoveKind k) {
  switch (k) {
    case MoveKind::Rapid: return "rapid";
    case MoveKind::Line: return "line";
    case MoveKind::Arc: return "arc";
  }
  return "line";
}

const char* centreFormName(CentreForm f) {
  switch (f) {
    case CentreForm::None: return "none";
    case CentreForm::Radius: return "R";
    case CentreForm::Incremental: return "IJ-incremental";
    case CentreForm::Reversed: return "IJ-reversed";
    case CentreForm::Absolute: return "IJ-absolute";
  }
  return "none";
}

/// How far the programmed arc's end lies off its circle, mm: for a move the wire offset made, the
/// arc its words gave, not the offset one.
double programmedRadiusError(const Toolpath& toolpath, std::size_t i) {
  const bool offset = i < toolpath.offsetRole.size() && toolpath.offsetRole[i] == OffsetRole::Element;
  return (offset ? toolpath.programmed[i] : toolpath.moves[i].lower).radiusError();
}

std::string blockText(const SourceFile& source, const Move& m) {
  return std::string(source.text().substr(m.span.offset, m.span.length));
}

std::string segmentText(const geometry::Segment& s, int decimals) {
  auto p = [&](const Vec2& v) { return formatFixed(v.x(), decimals) + " " + formatFixed(v.y(), decimals); };
  std::string out = s.isArc() ? std::string("arc ") + (s.sweep < 0 ? "cw " : "ccw ") : "line ";
  out += p(s.start) + " -> " + p(s.end);
  if (s.isArc())
    out += " centre " + p(s.centre) + " r " + formatFixed(s.radius(), decimals) + " sweep " +
           formatFixed(s.sweep * 180.0 / geometry::kPi, decimals);
  return out;
}

constexpr double kToDegrees = 180.0 / geometry::kPi;

/// Why the upper segment of a move is what it is, by dialect (for `kerf explain`).
std::string pairingReason(const Toolpath& tp, std::size_t i) {
  switch (tp.dialect) {
    case Dialect::Plain: return "the wire is vertical";
    case Dialect::XyuvAbs:
      return "the upper side is the block's U V words (absolute, same frame as X Y), with its own motion word and "
             "centre where given; without them the upper guide stays put";
    case Dialect::XyuvRel:
      return "the upper side is the programmed point plus the U V offset (upper minus lower) at each end; an arc's "
             "upper centre is the lower centre moved by K L";
    case Dialect::XyuvLinuxCnc:
      return "the upper side is the block's U V words (absolute, same frame as X Y), moved in a straight line "
             "during the block even when X Y follow an arc (LinuxCNC moves extra axes so)";
    case Dialect::SodickColon: return "the upper side is the words after ':' (absolute, its own modal motion)";
    case Dialect::TaperAngle: {
      const double degrees = tp.taperDegreesOf(i);
      if (degrees == 0.0) return "no taper is in force here: the wire is vertical";
      return std::string("the programmed contour offset by h tan(") + formatFixed(std::abs(degrees), 3) + "°) to the " +
             (degrees > 0 ? "left (G51)" : "right (G52)") +
             " of travel, h measured from the program plane; lines stay parallel, arcs concentric, corners sharp "
             "where the offsets meet";
    }
    case Dialect::TwoFile: return "the upper side is the move with the same index in the upper program";
  }
  return {};
}

}  // namespace

// ---- 2. check ----------------------------------------------------------------------------------

std::string formatDiagnosticsText(const Diagnostics& diags) {
  std::string out;
  for (const Diagnostic& d : diags.all()) out += formatDiagnostic(d);
  if (diags.dropped() > 0) out += "... and " + std::to_string(diags.dropped()) + " more diagnostics not shown\n";
  return out;
}

namespace {

/// A box as "X a .. b, Y c .. d".
std::string boxText(const geometry::Box& b) {
  return "X " + mm(b.min.x()) + " .. " + mm(b.max.x()) + ", Y " + mm(b.min.y()) + " .. " + mm(b.max.y());
}

/// The wire at its guides, two lines: where they are, what they travel, and U/V between them.
std::string guidesText(const PlaneHeights& h, const GuideTravel& g) {
  return "  guides: lower z " + mm(h.guides->lower) + ", upper z " + mm(h.guides->upper) + " — " + h.guidesSource +
         "\n    the lower guide travels " + boxText(g.lower) + "; the upper " + boxText(g.upper) +
         "; U/V between them up to " + mm(g.uvX) + " mm along X (line " + std::to_string(g.uvXLine) + "), " +
         mm(g.uvY) + " along Y (line " + std::to_string(g.uvYLine) + ")\n";
}

/// Minutes as the report writes them: one decimal, two below ten minutes.
std::string minutesText(double minutes) { return formatFixed(minutes, minutes < 10 ? 2 : 1); }

/// The time estimate, one line: "time 36.67 min (cutting 36.17, rapids 0.00, threading 0.50) at ...".
std::string timeText(const TimeEstimate& t) {
  if (t.passesTimed == 0 && !t.missing.empty()) return "  time not estimated: " + t.missing + "\n";
  std::string out = std::string("  time ") + (t.missing.empty() ? "" : "at least ") + minutesText(t.total()) +
                    " min (cutting " + minutesText(t.cutting) + ", rapids " + minutesText(t.rapids) + ", threading " +
                    minutesText(t.threading) + "): " + t.model + "\n";
  if (!t.missing.empty()) out += "    the rough cuts have no time: " + t.missing + "\n";
  return out;
}

/// The contours and their passes, one line each, for a program cut in several passes.
std::string structureText(const Structure& st) {
  std::string out;
  for (std::size_t ci = 0; ci < st.contours.size(); ++ci) {
    const Contour& c = st.contours[ci];
    out += "  contour " + std::to_string(ci + 1) + " from " + formatPoint(c.startHole) + ": " +
           plural(c.passes.size(), "pass") + "\n";
    for (std::size_t pi = 0; pi < c.passes.size(); ++pi) {
      const Pass& p = c.passes[pi];
      out += "    pass " + std::to_string(pi + 1) + ": lines " + std::to_string(p.firstLine) + "-" +
             std::to_string(p.lastLine) + ", " + offsetText(p) +
             (p.condition.empty() ? std::string() : ", " + p.condition) + ", " + directionName(p.direction) + ", " +
             (p.closes   ? std::string("closes")
              : p.cutOff ? std::string("cuts off the tab")
                         : "leaves a tab of " + mm(p.gap) + " mm") +
             ", " + mm(p.length) + " mm, " + (p.minutes ? minutesText(*p.minutes) + " min" : "no time") + "\n";
    }
  }
  return out;
}

}  // namespace

/// The program against --drawing: the worst deviation, and the worst ten elements past the
/// tolerance (JSON lists every element).
std::string comparisonText(const DrawingComparison& c) {
  auto um = [](double mm) { return formatFixed(mm * 1000.0, 1) + " µm"; };
  std::string out = "  drawing " + std::string(c.upper ? "(upper plane) " : "") + c.drawing + ": " +
                    plural(c.elements.size(), "element") + ", largest deviation " + um(c.worst) + " (tolerance " +
                    um(c.tolerance) + "), " + std::to_string(c.outOfTolerance) + " out of tolerance\n";
  std::vector<const ElementDeviation*> off;
  for (const ElementDeviation& e : c.elements)
    if (e.deviation > c.tolerance) off.push_back(&e);
  std::stable_sort(off.begin(), off.end(), [](const auto* a, const auto* b) { return a->deviation > b->deviation; });
  for (std::size_t k = 0; k < off.size() && k < 10; ++k)
    out += "    drawing line " + std::to_string(off[k]->drawingLine) + ": " + um(off[k]->deviation) + " at " +
           formatPoint(off[k]->at) + ", nearest block on line " + std::to_string(off[k]->blockLine) + "\n";
  if (off.size() > 10) out += "    and " + std::to_string(off.size() - 10) + " more (--json lists every element)\n";
  return out;
}

json comparisonJson(const DrawingComparison& c) {
  json elements = json::array(), edge = json::array();
  for (const ElementDeviation& e : c.elements)
    elements.push_back({{"element", e.element},
                        {"drawing_line", e.drawingLine},
                        {"deviation_mm", e.deviation},
                        {"at", vec(e.at)},
                        {"move", e.move},
                        {"block_line", e.blockLine}});
  for (const EdgeDeviation& e : c.edge)
    edge.push_back({{"move", e.move}, {"deviation_mm", e.deviation}, {"at", vec(e.at)}});
  json out = {{"drawing", c.drawing},
              {"tolerance_mm", c.tolerance},
              {"worst_mm", c.worst},
              {"out_of_tolerance", c.outOfTolerance},
              {"elements", std::move(elements)},
              {"edge", std::move(edge)}};
  if (c.placement)  // the drawing's point p lands at turn(angle) (mirror ? (-x, y) : p) + shift
    out["placement"] = {{"mirror", c.placement->mirror},
                        {"angle_deg", c.placement->angle * geometry::kDegreesPerRadian},
                        {"shift", vec(c.placement->shift)}};
  return out;
}

std::string formatSummaryText(const std::string& file, const Summary& s, const Diagnostics& diags) {
  std::string out;
  out += file + ": " + plural(diags.errorCount(), "error") + ", " + plural(diags.warningCount(), "warning") + "\n";
  if (s.format == InputFormat::ThreeB)
    out += "  read as 3B code: whole micrometres, each record relative to where the last one ended\n";
  else
    out += "  read for the " + s.reading.machine + " machine: integers in " + integerUnitName(s.reading.integerUnit) +
           ", I J " + arcCentreName(s.reading.arcCentre) + "\n";
  out += std::string(s.format == InputFormat::ThreeB ? "  records " : "  blocks ") + std::to_string(s.blocks) +
         ", moves " + std::to_string(s.moves) + " (" + std::to_string(s.cutMoves) + " cut: " +
         (s.taperProgram ? "lower " + plural(s.lines, "line") + ", " + plural(s.arcs, "arc") + ", upper " +
                               plural(s.upperLines, "line") + ", " + plural(s.upperArcs, "arc")
                         : plural(s.lines, "line") + ", " + plural(s.arcs, "arc")) +
         "; " + std::to_string(s.rapidMoves) + " rapid)\n";
  out += "  cut length " + mm(s.cutLength) + " mm, rapid length " + mm(s.rapidLength) + " mm\n";
  if (!s.bounds.empty())
    out += "  bounds X " + mm(s.bounds.min.x()) + " .. " + mm(s.bounds.max.x()) + ", Y " + mm(s.bounds.min.y()) +
           " .. " + mm(s.bounds.max.y()) + " mm\n";
  // A count past what any output writes says so: the summary promises no file of that many points.
  const std::string cap = s.points.points > kMaxPointsWritten
                              ? ", more than the " + std::to_string(kMaxPointsWritten) + " any output writes"
                              : std::string();
  out += "  points at " + samplingText(s.sampling) + ": " + std::to_string(s.points.points) + cap + " (max deviation " +
         formatFixed(s.points.maxDeviation, 6) + " mm, mean relative error " + sci(s.points.meanRelativeError) + ")\n";
  if (s.taper) {
    const TaperSummary& t = *s.taper;
    const geometry::Planes& p = t.heights.planes;
    out += std::string("  taper (") + dialectName(t.dialect) + "): lower z " + mm(p.lower) + ", upper z " +
           mm(p.upper) + ", height " + mm(p.height()) + " mm — " + t.heights.source + "\n";
    out += "  wire slope max " + formatFixed(t.maxSlopeDegrees, 3) + "° (line " + std::to_string(t.maxSlopeLine) +
           ", move " + std::to_string(t.maxSlopeMove) + "), min " + formatFixed(t.minSlopeDegrees, 3) + "° (line " +
           std::to_string(t.minSlopeLine) + ")\n";
    out += "  lower length " + mm(t.lowerLength) + " mm, upper length " + mm(t.upperLength) + " mm, surface " +
           mm(t.area) + " mm² in " + plural(t.patches, "patch") + "\n";
    if (t.guides) out += guidesText(t.heights, *t.guides);
  }
  if (s.structure.multiPass()) out += structureText(s.structure);
  if (s.comparison) out += comparisonText(*s.comparison);
  if (s.comparisonUpper) out += comparisonText(*s.comparisonUpper);
  if ((s.format == InputFormat::Iso || s.format == InputFormat::ThreeB) && s.cutMoves > 0)
    out += timeText(s.structure.time);
  out += std::string("verdict: ") + (diags.hasErrors() ? "errors — do not cut" : "ok") + "\n";
  return out;
}

namespace {

json segmentJson(const geometry::Segment& s) {
  json e;
  e["kind"] = s.isArc() ? "arc" : "line";
  e["start"] = vec(s.start);
  e["end"] = vec(s.end);
  if (s.isArc()) {
    e["centre"] = vec(s.centre);
    e["radius"] = s.radius();
    e["sweep"] = s.sweep;
  }
  return e;
}

/// A drawing's reading, contours and (with --offset and --side) their wire paths.
json drawingJson(const DrawingResult& drawing, const std::vector<ContourWire>* wires) {
  const Drawing& d = drawing.drawing;
  json dj;
  dj["version"] = d.version;
  dj["binary"] = d.binary;
  dj["ins_units"] = d.insUnits;
  dj["unit_to_mm"] = d.unitToMm;
  dj["entities"] = d.entities;
  if (d.curve) {
    json cj;
    cj["source"] = d.curve->points ? "points" : "expression";
    cj["tolerance_mm"] = d.curve->tolerance;
    cj["t"] = {d.curve->t0, d.curve->t1};
    cj["max_error_mm"] = d.curve->maxError;
    json spans = json::array();
    for (const geometry::BiarcSpan& sp : d.curve->spans)
      spans.push_back({{"t0", sp.t0}, {"t1", sp.t1}, {"error_mm", sp.error}, {"arcs", sp.count}});
    cj["spans"] = std::move(spans);
    dj["curve"] = std::move(cj);
  }
  dj["skipped"] = d.skipped;
  dj["elements"] = d.elements.size();
  json contours = json::array();
  for (const geometry::Chain& c : drawing.contours) {
    json cj;
    cj["elements"] = c.elements.size();
    cj["closed"] = c.closed;
    cj["gap"] = c.gap;
    double length = 0.0;
    for (const geometry::Segment& seg : c.path) length += seg.length();
    cj["length"] = length;
    cj["area"] = c.closed ? std::abs(geometry::signedArea(c.path)) : 0.0;
    cj["start"] = json::array({c.path.front().start.x(), c.path.front().start.y()});
    const std::size_t index = contours.size();
    if (wires && index < wires->size() && c.closed) {
      json path = json::array();
      for (const geometry::Segment& seg : c.path) path.push_back(segmentJson(seg));
      cj["path"] = std::move(path);
      const ContourWire& w = (*wires)[index];
      json wj;
      wj["offset"] = w.distance;
      wj["refused"] = w.refused;
      wj["degenerate"] = w.degenerate;
      json loops = json::array();
      double wireLength = 0.0, wireArea = 0.0;
      for (const auto& loop : w.loops) {
        json lj = json::array();
        std::vector<geometry::Segment> segs;
        for (const geometry::WirePiece& p : loop) {
          json pj = segmentJson(p.segment);
          pj["element"] = p.element;
          pj["corner"] = p.corner;
          lj.push_back(std::move(pj));
          segs.push_back(p.segment);
          wireLength += p.segment.length();
        }
        wireArea += geometry::signedArea(segs);
        loops.push_back(std::move(lj));
      }
      wj["loops"] = std::move(loops);
      wj["length"] = wireLength;
      wj["signed_area"] = wireArea;
      json lost = json::array();
      for (const geometry::LostRun& r : w.lost)
        lost.push_back({{"first", r.first},
                        {"count", r.count},
                        {"uncut", r.uncut},
                        {"where", vec(r.where)},
                        {"fillet", r.fillet}});
      wj["lost"] = std::move(lost);
      cj["wire"] = std::move(wj);
    }
    contours.push_back(std::move(cj));
  }
  dj["contours"] = std::move(contours);
  return dj;
}

}  // namespace

std::string checkReportJson(const std::string& file, const Summary& s, const Diagnostics& diags,
                            const DrawingResult* drawing, const std::vector<ContourWire>* wires) {
  json j;
  j["file"] = file;
  j["verdict"] = diags.hasErrors() ? "errors" : "ok";
  j["errors"] = diags.errorCount();
  j["warnings"] = diags.warningCount();
  j["diagnostics_not_shown"] = diags.dropped();
  json list = json::array();
  for (const Diagnostic& d : diags.all()) {
    json e;
    e["severity"] = severityName(d.severity);
    e["code"] = codeName(d.code);
    e["message"] = d.message;
    if (!d.help.empty()) e["help"] = d.help;
    if (d.source) e["file"] = d.source->name();
    if (d.source && !d.span.isWholeFile()) {
      const SourceLocation loc = d.source->locate(d.span.offset);
      e["line"] = loc.line;
      e["column"] = loc.column;
      e["length"] = d.span.length;
    }
    if (d.move) e["move"] = *d.move;
    if (d.point) e["point"] = json::array({d.point->x(), d.point->y(), d.point->z()});
    list.push_back(std::move(e));
  }
  j["diagnostics"] = std::move(list);
  json sum;
  sum["format"] = inputFormatName(s.format);
  if (drawing) j["drawing"] = drawingJson(*drawing, wires);
  sum["machine"] = s.reading.machine;
  sum["integer_unit"] = integerUnitName(s.reading.integerUnit);
  sum["arc_centre"] = arcCentreName(s.reading.arcCentre);
  sum["dialect"] = dialectName(s.dialect);
  sum["blocks"] = s.blocks;
  sum["moves"] = s.moves;
  sum["cut_moves"] = s.cutMoves;
  sum["rapid_moves"] = s.rapidMoves;
  sum["lines"] = s.lines;
  sum["arcs"] = s.arcs;
  if (s.taperProgram) {
    sum["upper_lines"] = s.upperLines;
    sum["upper_arcs"] = s.upperArcs;
  }
  sum["cut_length_mm"] = s.cutLength;
  sum["rapid_length_mm"] = s.rapidLength;
  if (!s.bounds.empty()) sum["bounds_mm"] = {{"min", vec(s.bounds.min)}, {"max", vec(s.bounds.max)}};
  sum["sampling"] = samplingJson(s.sampling);
  sum["points"] = s.points.points;
  sum["max_deviation_mm"] = s.points.maxDeviation;
  sum["mean_relative_error"] = s.points.meanRelativeError;
  if (s.taper) {
    const TaperSummary& t = *s.taper;
    sum["taper"] = {{"dialect", dialectName(t.dialect)},   {"lower_z", t.heights.planes.lower},
                    {"upper_z", t.heights.planes.upper},   {"program_z", t.heights.programZ},
                    {"height", t.heights.planes.height()}, {"heights_from", t.heights.source},
                    {"max_slope_deg", t.maxSlopeDegrees},  {"max_slope_move", t.maxSlopeMove},
                    {"max_slope_line", t.maxSlopeLine},    {"min_slope_deg", t.minSlopeDegrees},
                    {"min_slope_move", t.minSlopeMove},    {"min_slope_line", t.minSlopeLine},
                    {"lower_length_mm", t.lowerLength},    {"upper_length_mm", t.upperLength},
                    {"surface_area_mm2", t.area},          {"patches", t.patches}};
    if (t.guides) {
      const GuideTravel& g = *t.guides;
      auto box = [&](const geometry::Box& b) { return json{{"min", vec(b.min)}, {"max", vec(b.max)}}; };
      sum["taper"]["guides"] = {{"lower_z", t.heights.guides->lower}, {"upper_z", t.heights.guides->upper},
                                {"from", t.heights.guidesSource},     {"lower_bounds_mm", box(g.lower)},
                                {"upper_bounds_mm", box(g.upper)},    {"uv_max_x_mm", g.uvX},
                                {"uv_max_x_line", g.uvXLine},         {"uv_max_y_mm", g.uvY},
                                {"uv_max_y_line", g.uvYLine}};
    }
  }
  sum["structure"] = structureObject(s.structure);
  if (s.comparison) sum["comparison"] = comparisonJson(*s.comparison);
  if (s.comparisonUpper) sum["comparison_upper"] = comparisonJson(*s.comparisonUpper);
  j["summary"] = std::move(sum);
  roundNumbers(j);
  return j.dump(2) + "\n";
}

std::string structureJson(const Structure& structure) { return structureObject(structure).dump(); }

std::string formatTrace(const Toolpath& toolpath, const Diagnostics& diags) {
  auto f6 = [](double v) { return formatFixed(v, 6); };
  auto p6 = [&](const Vec2& p) { return f6(p.x()) + " " + f6(p.y()); };
  std::string out = "start " + p6(toolpath.start) + "\n";
  if (toolpath.isTaper()) {
    const PlaneHeights& h = toolpath.heights;
    out += std::string("dialect ") + dialectName(toolpath.dialect) + " heights " +
           (h.known ? "lower " + f6(h.planes.lower) + " upper " + f6(h.planes.upper) + " program " + f6(h.programZ)
                    : std::string("unknown")) +
           "\n";
  }
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& m = toolpath.moves[i];
    const geometry::Segment& s = m.lower;
    out += std::to_string(m.line) + " " + kindName(m.kind);
    if (m.kind == MoveKind::Arc) out += s.sweep < 0 ? " cw" : " ccw";
    out += " " + p6(s.start) + " -> " + p6(s.end);
    if (m.kind == MoveKind::Arc)
      out += " centre " + p6(s.centre) + " r " + f6(s.radius()) + " sweep " + f6(s.sweep * 180.0 / geometry::kPi) +
             " from " + centreFormName(m.centreForm);
    if (m.callDepth > 0) out += " depth " + std::to_string(m.callDepth);
    out += "\n";
    if (toolpath.isTaper()) out += "  upper " + segmentText(toolpath.upper[i], 6) + "\n";
  }
  out += std::string("ended ") + (toolpath.endedProperly ? "yes" : "no") + "\n";
  for (const Diagnostic& d : diags.all()) {
    out += "diagnostic ";
    if (d.source && !d.span.isWholeFile()) {
      const SourceLocation loc = d.source->locate(d.span.offset);
      out += std::to_string(loc.line) + ":" + std::to_string(loc.column) + " ";
    }
    out += std::string(severityName(d.severity)) + " " + codeName(d.code) + " " + d.message + "\n";
  }
  return out;
}

// ---- 3. explain --------------------------------------------------------------------------------

namespace {

/// The explanation's first lines: the file, the sampling, the angle convention, the start, the planes.
std::string explainHeader(const SourceFile& source, const Toolpath& toolpath, const geometry::Sampling& sampling) {
  std::string out;
  out += "Kerf explains " + source.name() + ": " + plural(toolpath.moves.size(), "move") + ", arcs sampled at " +
         samplingText(sampling) + "\n";
  out += "Angles: counter-clockwise from +X unless marked 'seed', which is the paper's clockwise convention.\n";
  out += "The wire starts at " + formatPoint(toolpath.start) + ".\n";
  if (toolpath.isTaper()) {
    const PlaneHeights& h = toolpath.heights;
    out += std::string("4-axis taper, dialect ") + dialectName(toolpath.dialect) +
           ": each move is a ruled patch; the "
           "wire at t joins lower(t) and upper(t), t proportional to arc length on each side.\n";
    out += h.known
               ? "Planes: " + h.source + "; slope = atan(|upper(t) - lower(t)| / " + mm(h.planes.height()) + " mm).\n"
               : std::string("The plane heights are not known, so slopes cannot be given.\n");
  }
  return out;
}

/// What the wire offset made of move i (nothing where none was applied).
std::string explainOffsetRole(const Toolpath& toolpath, std::size_t i) {
  if (i >= toolpath.offsetRole.size()) return {};
  const geometry::Segment& p = toolpath.programmed[i];
  switch (toolpath.offsetRole[i]) {
    case OffsetRole::None: return {};
    case OffsetRole::Element:
      return "  wire offset: the wire-centre path below is this block's programmed " + segmentText(p, 3) +
             " moved sideways by the offset (an arc keeps its centre, its radius grows or shrinks)\n";
    case OffsetRole::Corner:
      return "  wire offset: no block of its own: the wire rolls round the convex corner at " + formatPoint(p.start) +
             " on an arc of the offset radius about it\n";
    case OffsetRole::StartUp:
      return "  wire offset starts: programmed " + segmentText(p, 3) +
             "; the wire goes from the programmed start to the offset path\n";
    case OffsetRole::Cancel:
      return "  wire offset cancelled: programmed " + segmentText(p, 3) +
             "; the wire leaves the offset path for the programmed end\n";
  }
  return {};
}

/// Move i of a taper program: its upper side, how it pairs with the lower, its slope.
std::string explainUpper(const Toolpath& toolpath, std::size_t i) {
  const geometry::Segment& s = toolpath.moves[i].lower;
  const geometry::Segment& u = toolpath.upper[i];
  std::string out = "  upper: " + segmentText(u, 3) + ", length " + mm(u.length()) + " mm\n";
  out += "  pairing: " + pairingReason(toolpath, i) + "\n";
  if (toolpath.heights.known) {
    const geometry::Planes& pl = toolpath.heights.planes;
    const geometry::PatchMeasures pm = geometry::measurePatch(s, u, pl);
    out += "  slope " + formatFixed(geometry::slopeAt(s, u, pl, 0.0) * kToDegrees, 3) + "° at the start, " +
           formatFixed(geometry::slopeAt(s, u, pl, 1.0) * kToDegrees, 3) + "° at the end, steepest " +
           formatFixed(pm.maxSlope.value * kToDegrees, 3) + "° at t = " + formatFixed(pm.maxSlope.t, 3) +
           (pm.exact ? " (closed form)" : " (sampled and refined)") + "\n";
  }
  return out + "  lower:\n";
}

/// The lower side of move i: a line's length, or how an arc's centre follows from its words.
void explainLower(std::string& out, const Toolpath& toolpath, std::size_t i, const geometry::Sampling& sampling) {
  const Move& m = toolpath.moves[i];
  const geometry::Segment& s = m.lower;
  const bool threeB = toolpath.format == InputFormat::ThreeB;
  if (m.kind != MoveKind::Arc) {
    if (threeB)
      out +=
          "  3B line: x y give the direction (their signs from L, the end's quadrant), J the length along the "
          "count axis G; end = start + (x, y) J / (x for GX, y for GY)\n";
    out += std::string("  ") + (m.kind == MoveKind::Rapid ? "rapid (G00, not cut)" : "straight cut (G01)") + " from " +
           formatPoint(s.start) + " to " + formatPoint(s.end) + ", length " + mm(s.length()) + " mm\n";
    if (m.kind == MoveKind::Line) out += "  a line adds only its end point to the point sequence\n";
    return;
  }
  const bool cw = s.sweep < 0;
  out += std::string("  arc ") + (cw ? "clockwise (G02)" : "counter-clockwise (G03)") + " from " +
         formatPoint(s.start) + " (the end of the previous move) to " + formatPoint(s.end) + "\n";
  // Where G41/G42 was applied, the centre follows from the words on the programmed arc (a corner
  // arc has no words: its centre is the programmed corner).
  const OffsetRole role = i < toolpath.offsetRole.size() ? toolpath.offsetRole[i] : OffsetRole::None;
  const geometry::Segment& d = role == OffsetRole::Element ? toolpath.programmed[i] : s;
  if (role == OffsetRole::Corner) {
    out += "  centre " + formatPoint(s.centre) + ": the programmed corner; radius = the wire offset " + mm(s.radius()) +
           " mm\n";
  } else if (const Toolpath::CornerMade* corner = toolpath.cornerAt(i); corner && m.centreForm == CentreForm::None) {
    out += "  centre " + formatPoint(d.centre) + ": the fillet of the corner word, radius " + mm(corner->size) +
           " mm, tangent to the elements that met at " + formatPoint(corner->sharp) + "\n";
  } else if (m.centreForm == CentreForm::Radius) {
    const double r = toolpath.programmedRadius(i);
    const int zn =
        geometry::seedSignFactor(cw ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise, r);
    out += "  centre " + formatPoint(d.centre) + " from R " + mm(r) + ": half the chord" +
           (role == OffsetRole::Element ? " of the programmed arc" : "") + " is " + mm((d.end - d.start).norm() / 2) +
           " mm; " +
           (r > 0 ? "R > 0 takes the arc of at most 180 degrees" : "R < 0 takes the arc longer than 180 degrees") +
           " (seed formulas (1)-(2) with signs restored, sign factor zn = " + (zn > 0 ? "+1" : "-1") + ")\n";
  } else if (threeB) {
    const Vec2 xy = toolpath.programmedCentreWords(i);
    out += "  3B arc: x y = start - centre = (" + mm(xy.x()) + ", " + mm(xy.y()) +
           ") (signs from the start's quadrant in SR/NR), so the centre is " + formatPoint(s.centre) + ", radius " +
           mm(s.radius()) +
           " mm; the arc ends where it has travelled J along the count axis, over every quadrant it "
           "crosses\n";
  } else {
    const Vec2 ij = toolpath.programmedCentreWords(i);
    const std::string rule = arcCentreRule(arcCentreOf(m.centreForm));
    out += "  centre " + formatPoint(d.centre) + " from I " + mm(ij.x()) + " J " + mm(ij.y()) + ": " + rule +
           (role == OffsetRole::Element ? " (the programmed start " + formatPoint(d.start) + ")" : std::string()) +
           "; radius by formula (3) = |start - centre| = " + mm(d.radius()) + " mm\n";
    if (const double error = programmedRadiusError(toolpath, i); std::abs(error) > 0.0005)
      out += "  the end point is " + mm(std::abs(error)) + " mm off that circle (within the accepted tolerance)\n";
  }
  if (role == OffsetRole::Element)
    out += "  the wire path keeps that centre, " + std::string(s.radius() > d.radius() ? "outside" : "inside") +
           " the programmed arc by the offset\n";
  out += "  radius " + mm(s.radius()) + " mm, sweep " + deg(std::abs(s.sweep)) + " degrees, length " + mm(s.length()) +
         " mm\n";
  const geometry::ArcSampleStats st = geometry::sample(s, sampling, nullptr);  // counts only
  if (sampling.mode == geometry::SamplingMode::Step) {
    const geometry::SeedArcAngles a = geometry::seedAngles(s, sampling.value);
    out += "  seed angles: alpha " + deg(a.alpha) + ", beta " + deg(a.beta) +
           ", gamma = 2 asin(k / 2R) = " + deg(a.gamma) + " degrees; delta " + (cw ? "grows" : "falls") +
           " by gamma from alpha to beta\n";
  }
  out += "  " + plural(st.points, "point") + " after the start, max deviation " + formatFixed(st.maxDeviation, 6) +
         " mm, mean relative error " + sci(st.meanRelativeError) + "\n";
}

/// Where the passes begin and end (a program cut in several passes), for `kerf explain`.
struct PassMarks {
  std::vector<std::string> before, after;  ///< per move: the lines before and after its explanation
  std::vector<std::string> role;           ///< per move: "" or "lead-in of pass 2" / "lead-out of pass 2"
};

PassMarks passMarks(const Structure* structure, std::size_t moves) {
  PassMarks marks{std::vector<std::string>(moves), std::vector<std::string>(moves), std::vector<std::string>(moves)};
  if (!structure || !structure->multiPass()) return marks;
  for (std::size_t ci = 0; ci < structure->contours.size(); ++ci) {
    const Contour& c = structure->contours[ci];
    for (std::size_t k = 0; k < c.passes.size(); ++k) {
      const Pass& p = c.passes[k];
      if (p.first >= p.end || p.end > moves) continue;
      const std::string name = passName(ci, k);
      const int kept = keptSide(p);
      const std::string what = passRole(p, k);
      marks.before[p.first] = "\n== " + name + " begins (" + std::to_string(c.passes.size()) +
                              " passes from the hole at " + formatPoint(c.startHole) + "): " + what + ", " +
                              offsetText(p) + ", " + directionName(p.direction) +
                              (kept > 0   ? ", inside its contour"
                               : kept < 0 ? ", outside its contour"
                                          : "") +
                              "\n";
      marks.after[p.end - 1] = "== " + name + " ends: " +
                               (p.closes   ? std::string("it closes the contour")
                                : p.cutOff ? std::string("the tab is cut off")
                                           : "it leaves a tab of " + mm(p.gap) + " mm") +
                               "; " + mm(p.length) + " mm" +
                               (p.minutes ? ", about " + minutesText(*p.minutes) + " min" : std::string()) + "\n";
      for (std::size_t m = p.first; m < p.alongFirst && m < moves; ++m)
        marks.role[m] = "  lead-in of " + name + ": from the hole to the contour\n";
      for (std::size_t m = p.alongEnd; m < p.end; ++m)
        marks.role[m] = "  lead-out of " + name + ": back from the contour\n";
    }
  }
  return marks;
}

}  // namespace

std::string explainText(const SourceFile& source, const Toolpath& toolpath, const geometry::Sampling& sampling,
                        const Structure* structure, const ParseOptions& parse) {
  std::string out = explainHeader(source, toolpath, sampling);
  const PassMarks marks = passMarks(structure, toolpath.moves.size());
  std::vector<std::string> modes;  // in force at the move before: said again where they change
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    out += marks.before[i];
    if (std::vector<std::string> now = blockModes(toolpath, i); now != modes) {
      out += "\nmodes from line " + std::to_string(toolpath.moves[i].line) + ":\n";
      for (const std::string& m : now) out += "  " + m + "\n";
      modes = std::move(now);
    }
    out += "\nline " + std::to_string(toolpath.moves[i].line) + ": " + blockText(source, toolpath.moves[i]) + "\n";
    for (const WordMeaning& w : blockWords(source, toolpath, i, parse)) out += "  " + w.word + ": " + w.sets + "\n";
    out += marks.role[i];
    out += explainOffsetRole(toolpath, i);
    if (toolpath.isTaper()) out += explainUpper(toolpath, i);
    explainLower(out, toolpath, i, sampling);
    out += marks.after[i];
  }
  return out;
}

std::string explainJson(const SourceFile& source, const Toolpath& toolpath, const geometry::Sampling& sampling,
                        const Structure* structure, const ParseOptions& parse) {
  // A program cut in several passes: each move's contour and pass (1-based) and its role in it.
  std::vector<json> passOf(toolpath.moves.size());
  if (structure && structure->multiPass())
    for (std::size_t ci = 0; ci < structure->contours.size(); ++ci)
      for (std::size_t k = 0; k < structure->contours[ci].passes.size(); ++k) {
        const Pass& p = structure->contours[ci].passes[k];
        for (std::size_t m = p.first; m < p.end && m < passOf.size(); ++m)
          passOf[m] = {{"contour", ci + 1},
                       {"pass", k + 1},
                       {"role", m < p.alongFirst  ? "lead-in"
                                : m >= p.alongEnd ? "lead-out"
                                                  : "contour"}};
      }
  json j;
  j["file"] = source.name();
  j["sampling"] = samplingJson(sampling);
  j["start"] = vec(toolpath.start);
  j["format"] = toolpath.format == InputFormat::ThreeB ? "3b" : "iso";
  json moves = json::array();
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& m = toolpath.moves[i];
    const geometry::Segment& s = m.lower;
    json e;
    e["index"] = i;
    e["line"] = m.line;
    e["block"] = blockText(source, m);
    e["kind"] = kindName(m.kind);
    e["start"] = vec(s.start);
    e["end"] = vec(s.end);
    e["length"] = s.length();
    if (toolpath.isTaper()) {
      const geometry::Segment& u = toolpath.upper[i];
      json up;
      up["kind"] = u.isArc() ? "arc" : "line";
      up["start"] = vec(u.start);
      up["end"] = vec(u.end);
      up["length"] = u.length();
      if (u.isArc()) {
        up["centre"] = vec(u.centre);
        up["radius"] = u.radius();
        up["direction"] = u.sweep < 0 ? "cw" : "ccw";
      }
      up["pairing"] = pairingReason(toolpath, i);
      if (toolpath.heights.known) {
        up["slope_start_deg"] = geometry::slopeAt(s, u, toolpath.heights.planes, 0.0) * kToDegrees;
        up["slope_end_deg"] = geometry::slopeAt(s, u, toolpath.heights.planes, 1.0) * kToDegrees;
      }
      e["upper"] = std::move(up);
    }
    if (m.kind == MoveKind::Arc) {
      e["centre"] = vec(s.centre);
      e["radius"] = s.radius();
      e["direction"] = s.sweep < 0 ? "cw" : "ccw";
      e["sweep_deg"] = std::abs(s.sweep) * 180.0 / geometry::kPi;
      e["centre_from"] = toolpath.format == InputFormat::ThreeB ? "3B-xy" : centreFormName(m.centreForm);
      if (toolpath.format == InputFormat::ThreeB) {
        e["xy"] = vec(toolpath.programmedCentreWords(i));
      } else if (m.centreForm == CentreForm::Radius) {
        e["R"] = toolpath.programmedRadius(i);
        e["zn"] = geometry::seedSignFactor(
            s.sweep < 0 ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise,
            toolpath.programmedRadius(i));
      } else {
        e["IJ"] = vec(toolpath.programmedCentreWords(i));
        e["radius_error"] = programmedRadiusError(toolpath, i);
      }
      const geometry::ArcSampleStats st = geometry::sample(s, sampling, nullptr);
      e["points"] = st.points;
      e["max_deviation"] = st.maxDeviation;
      e["mean_relative_error"] = st.meanRelativeError;
    } else {
      e["points"] = 1;
    }
    if (!passOf[i].is_null()) e["pass"] = std::move(passOf[i]);
    json words = json::array();
    for (const WordMeaning& w : blockWords(source, toolpath, i, parse))
      words.push_back({{"word", w.word}, {"sets", w.sets}});
    e["words"] = std::move(words);
    e["modes"] = blockModes(toolpath, i);
    moves.push_back(std::move(e));
  }
  j["moves"] = std::move(moves);
  roundNumbers(j);
  return j.dump(2) + "\n";
}

}  // namespace kerf::converter
