#include "kerf/converter/formats/points/points.h"

#include <array>

#include "kerf/converter/check/summary.h"
#include "kerf/converter/nc/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>

namespace kerf::converter {

PointProfile bp95dProfile() { return PointProfile{}; }

namespace {

std::string unquote(std::string_view v, bool& ok) {
  ok = true;
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') {
    std::string out;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      if (v[i] == '\\' && i + 2 < v.size()) {
        const char e = v[++i];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      } else {
        out += v[i];
      }
    }
    return out;
  }
  if (!v.empty() && (v.front() == '"' || v.back() == '"')) ok = false;
  return std::string(v);
}

}  // namespace

namespace {

/// One `key = value` line of a point profile: where its parts are, and how a wrong value is said.
struct ProfileLine {
  std::string_view key, value;
  std::size_t keyCol = 0, valueCol = 0;
  std::function<void(std::size_t, std::size_t, const std::string&, const std::string&)> fail;

  void failValue(const std::string& message) const { fail(valueCol, value.size(), message, {}); }
  bool integer(long lo, long hi, long& out) const {
    long v = 0;
    const auto r = std::from_chars(value.data(), value.data() + value.size(), v);
    if (r.ec != std::errc{} || r.ptr != value.data() + value.size() || v < lo || v > hi) {
      failValue(std::string(key) + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
      return false;
    }
    out = v;
    return true;
  }
  void boolean(bool& out) const {
    if (value == "true" || value == "yes")
      out = true;
    else if (value == "false" || value == "no")
      out = false;
    else
      failValue(std::string(key) + " must be true or false");
  }
  /// One of two words: `no` gives false, `yes` true.
  void either(std::string_view no, std::string_view yes, bool& out, const char* message) const {
    if (value == no)
      out = false;
    else if (value == yes)
      out = true;
    else
      failValue(message);
  }
  /// The line's value set on p (its errors said through fail).
  void applyTo(PointProfile& p) const {
    bool quotedOk = true;
    long v = 0;
    if (key == "name") {
      p.name = unquote(value, quotedOk);
    } else if (key == "decimals") {
      if (integer(0, 6, v)) p.decimals = static_cast<int>(v);
    } else if (key == "unit") {
      either("mm", "um", p.micrometres, "unit must be mm or um");
    } else if (key == "coordinates") {
      either("absolute", "incremental", p.incremental, "coordinates must be absolute or incremental");
    } else if (key == "separator") {
      p.separator = value == "space"       ? " "
                    : value == "tab"       ? "\t"
                    : value == "comma"     ? ","
                    : value == "semicolon" ? ";"
                                           : unquote(value, quotedOk);
    } else if (key == "line_numbers") {
      boolean(p.lineNumbers);
    } else if (key == "line_number_prefix") {
      p.lineNumberPrefix = unquote(value, quotedOk);
    } else if (key == "line_number_start") {
      if (integer(0, 1000000000, v)) p.lineNumberStart = static_cast<std::size_t>(v);
    } else if (key == "header") {
      p.header = unquote(value, quotedOk);
    } else if (key == "footer") {
      p.footer = unquote(value, quotedOk);
    } else if (key == "max_points") {
      if (integer(2, 100000000, v)) p.maxPoints = static_cast<std::size_t>(v);
    } else {
      fail(keyCol, key.size(), "unknown profile key '" + std::string(key) + "'",
           "keys: name, decimals, unit, coordinates, separator, line_numbers, line_number_prefix, "
           "line_number_start, header, footer, max_points");
    }
    if (!quotedOk) failValue("unbalanced quote in the value");
  }
};

}  // namespace

std::optional<PointProfile> parseProfile(const SourceFile& file, Diagnostics& diags) {
  PointProfile p = bp95dProfile();
  p.name = "custom";
  bool ok = true;
  const std::string_view text = file.text();
  for (std::uint32_t line = 1; line <= file.lineCount(); ++line) {
    const std::string_view raw = file.lineText(line);
    const auto lineOffset = static_cast<std::uint32_t>(raw.data() - text.data());
    std::string_view body = raw;
    if (const std::size_t hash = body.find('#'); hash != std::string_view::npos && body.find('"') > hash)
      body = body.substr(0, hash);
    if (trimBlanks(body).empty()) continue;
    auto fail = [&](std::size_t col, std::size_t len, const std::string& msg, const std::string& help) {
      diags.error(
          Code::ProfileError, &file,
          {lineOffset + static_cast<std::uint32_t>(col), static_cast<std::uint32_t>(std::max<std::size_t>(len, 1))},
          msg, help);
      ok = false;
    };
    const std::size_t eq = body.find('=');
    if (eq == std::string_view::npos) {
      fail(static_cast<std::size_t>(trimBlanks(body).data() - raw.data()), trimBlanks(body).size(),
           "expected 'key = value'", {});
      continue;
    }
    ProfileLine l;
    l.key = trimBlanks(body.substr(0, eq));
    l.value = trimBlanks(body.substr(eq + 1));
    l.valueCol = static_cast<std::size_t>(l.value.data() - raw.data());
    l.keyCol = static_cast<std::size_t>(l.key.data() - raw.data());
    l.fail = fail;
    l.applyTo(p);
  }
  if (!ok) return std::nullopt;
  return p;
}

namespace {

using Row = std::array<double, 4>;

/// The point file: header, one row per line (columns values each), footer.
std::string writeRows(const std::vector<Row>& rows, std::size_t columns, const PointProfile& profile) {
  std::string text;
  text.reserve(rows.size() * 10 * columns + profile.header.size() + profile.footer.size());
  if (!profile.header.empty()) {
    text += profile.header;
    if (text.back() != '\n') text += '\n';
  }
  const double scale = profile.micrometres ? 1000.0 : 1.0;
  const int decimals = profile.micrometres ? 0 : profile.decimals;
  // Incremental output is the difference of rounded absolute values, so the increments add
  // up exactly to every absolute point (no drift from rounding).
  const double f = std::pow(10.0, decimals);
  const double unitStep = 1.0 / f;
  Row prev{};
  std::size_t number = profile.lineNumberStart;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (profile.lineNumbers) text += profile.lineNumberPrefix + std::to_string(number++) + profile.separator;
    for (std::size_t c = 0; c < columns; ++c) {
      const double r = std::nearbyint(rows[i][c] * scale * f);
      const double w = profile.incremental && i > 0 ? r - prev[c] : r;
      prev[c] = r;
      if (c > 0) text += profile.separator;
      text += formatFixed(w * unitStep, decimals);
    }
    text += '\n';
  }
  if (!profile.footer.empty()) {
    text += profile.footer;
    if (text.back() != '\n') text += '\n';
  }
  return text;
}

}  // namespace

std::optional<PointOutput> emitPoints(const Toolpath& toolpath, const SourceFile* source, const PointProfile& profile,
                                      const PointRequest& request, Diagnostics& diags) {
  CutPath path = cutPath(toolpath);
  if (path.segments.empty()) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(),
                "nothing to write: the program has no cutting move");
    return std::nullopt;
  }
  if (request.startLine && !startCutPathAt(toolpath, path, *request.startLine, source, diags)) return std::nullopt;

  PointOutput out;
  out.sampling = request.sampling;
  std::size_t planned = geometry::samplePath(path.segments, out.sampling, nullptr).points;
  const std::optional<std::size_t> capacity = request.maxPoints ? request.maxPoints : profile.maxPoints;
  // Keep the requested sampling when it fits; otherwise the finest one that does.
  if (capacity && planned > *capacity) {
    const geometry::CapacityFit fit = geometry::fitToCapacity(path.segments, *capacity, request.sampling.mode);
    if (!fit.fits) {
      diags.error(Code::CapacityTooSmall, source, SourceSpan::wholeFile(),
                  "the path needs at least " + std::to_string(fit.fewestPossible) +
                      " points (every arc as coarse as it can be), more than the " + std::to_string(*capacity) +
                      " the controller holds");
      return std::nullopt;
    }
    out.sampling = fit.sampling;
    out.fitted = true;
    planned = fit.points;
  }
  if (planned > kMaxPointsWritten) {
    diags.error(Code::CapacityTooSmall, source, SourceSpan::wholeFile(),
                "the step gives " + std::to_string(planned) + " points, more than Kerf writes (" +
                    std::to_string(kMaxPointsWritten) + ")",
                "use a coarser --step or --tolerance, or --max-points");
    return std::nullopt;
  }
  std::vector<geometry::Vec2> points;
  out.stats = geometry::samplePath(path.segments, out.sampling, &points);
  out.points = points.size();

  std::vector<Row> rows(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) rows[i] = {points[i].x(), points[i].y(), 0.0, 0.0};
  out.text = writeRows(rows, 2, profile);
  return out;
}

std::optional<PointOutput> emitPoints4(const Toolpath& toolpath, const SourceFile* source, const PointProfile& profile,
                                       const PointRequest& request, bool relativeUv, Diagnostics& diags) {
  if (!toolpath.isTaper()) {
    diags.error(Code::OptionDoesNotFit, source, SourceSpan::wholeFile(),
                "points4 writes both planes, and this program has no upper contour", "use --to bp95d");
    return std::nullopt;
  }
  if (request.atGuides && !(toolpath.heights.guides && toolpath.heights.known)) {
    diags.error(Code::GuidesUnknown, source, SourceSpan::wholeFile(),
                "--plane guides writes the wire at its guides, and no guide heights are given",
                "give --guides LOWER_Z,UPPER_Z (the part's lower face at 0), cnc3's M100 P Q in the program, or a "
                "machine profile with guides");
    return std::nullopt;
  }
  // At the guides each row's wire is extended: lower + (upper - lower) (z - z_lower) / H.
  const geometry::Planes& faces = toolpath.heights.planes;
  const double a = request.atGuides ? (toolpath.heights.guides->lower - faces.lower) / faces.height() : 0.0;
  const double b = request.atGuides ? (toolpath.heights.guides->upper - faces.lower) / faces.height() : 1.0;
  constexpr double kJoin = 1e-9;
  // Counted in closed form before anything is sampled: a budget is refused before it is spent.
  auto samplesOf = [&](std::size_t i) {
    return std::max(geometry::sampleCount(toolpath.moves[i].lower, request.sampling),
                    geometry::sampleCount(toolpath.upper[i], request.sampling));
  };
  // The cut moves, each with whether it starts where the previous one ended (no start point of
  // its own), decided once for the count and the rows alike.
  std::vector<std::pair<std::size_t, bool>> cuts;
  std::size_t planned = 0;
  {
    geometry::Vec2 lastLower(0, 0), lastUpper(0, 0);
    for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
      if (!toolpath.moves[i].isCut()) continue;
      const geometry::Segment& lo = toolpath.moves[i].lower;
      const geometry::Segment& up = toolpath.upper[i];
      const bool joins =
          !cuts.empty() && (lo.start - lastLower).norm() <= kJoin && (up.start - lastUpper).norm() <= kJoin;
      cuts.emplace_back(i, joins);
      planned += samplesOf(i) + (joins ? 0 : 1);
      if (planned > kMaxPointsWritten) {
        diags.error(Code::CapacityTooSmall, source, SourceSpan::wholeFile(),
                    "the step gives more points than Kerf writes (" + std::to_string(kMaxPointsWritten) + ")",
                    "use a coarser --step or --tolerance");
        return std::nullopt;
      }
      lastLower = lo.end;
      lastUpper = up.end;
    }
  }
  if (planned == 0) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(),
                "nothing to write: the program has no cutting move");
    return std::nullopt;
  }
  const std::optional<std::size_t> capacity = request.maxPoints ? request.maxPoints : profile.maxPoints;
  if (capacity && planned > *capacity) {
    diags.error(Code::CapacityTooSmall, source, SourceSpan::wholeFile(),
                std::to_string(planned) + " point pairs at this step, more than the " + std::to_string(*capacity) +
                    " the controller holds",
                "use a coarser --step or --tolerance (points4 does not fit the step by itself)");
    return std::nullopt;
  }
  PointOutput out;
  std::vector<Row> rows;
  rows.reserve(planned);
  for (const auto& [i, joins] : cuts) {
    const geometry::Segment& lo = toolpath.moves[i].lower;
    const geometry::Segment& up = toolpath.upper[i];
    const std::size_t n = samplesOf(i);
    auto push = [&](const geometry::Vec2& faceLower, const geometry::Vec2& faceUpper) {
      const geometry::Vec2 l = faceLower + a * (faceUpper - faceLower);
      const geometry::Vec2 u = faceLower + b * (faceUpper - faceLower);
      const geometry::Vec2 uv = relativeUv ? geometry::Vec2(u - l) : u;
      rows.push_back({l.x(), l.y(), uv.x(), uv.y()});
    };
    if (!joins) push(lo.start, up.start);
    // The chords of n equal steps of an arc lie r (1 - cos(sweep / 2n)) from it at most; a guide's
    // path, lower + s (upper - lower), from its chords by at most |1 - s| and |s| times the two.
    double deviation[2] = {0.0, 0.0};
    for (int side = 0; side < 2; ++side) {
      const geometry::Segment& seg = side == 0 ? lo : up;
      if (seg.isArc())
        deviation[side] = seg.radius() * (1.0 - std::cos(std::abs(seg.sweep) / (2.0 * static_cast<double>(n))));
    }
    for (const double s : {a, b})
      out.stats.maxDeviation =
          std::max(out.stats.maxDeviation, std::abs(1.0 - s) * deviation[0] + std::abs(s) * deviation[1]);
    // Both planes at the same t, so each pair is one position of the wire.
    for (std::size_t k = 1; k <= n; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(n);
      push(k == n ? lo.end : lo.pointAt(t), k == n ? up.end : up.pointAt(t));
    }
  }
  out.sampling = request.sampling;
  out.points = rows.size();
  out.stats.points = rows.size();
  out.text = writeRows(rows, 4, profile);
  return out;
}

namespace {

/// pairs: points4 (an X Y U V pair a line, in the profile's number format).
EmitOutput fromPoints(PointOutput&& p, const PointWriteOptions& request, bool pairs = false) {
  EmitOutput out;
  out.text = std::move(p.text);
  out.what = pairs ? std::to_string(p.points) + " point pairs (points4: X Y U V, numbers as the " +
                         request.profile.name + " profile writes them)"
                   : std::to_string(p.points) + " points (" + request.profile.name + " profile)";
  const std::size_t capacity =
      request.request.maxPoints ? *request.request.maxPoints : request.profile.maxPoints.value_or(0);
  out.detail = std::string("; ") + (p.sampling.mode == geometry::SamplingMode::Step ? "step k = " : "tolerance ") +
               formatFixed(p.sampling.value, 6) + " mm" +
               (p.fitted ? " chosen to fit " + std::to_string(capacity) + " points" : "") + ", max deviation " +
               formatFixed(p.stats.maxDeviation, 6) + " mm";
  return out;
}

}  // namespace

std::optional<EmitOutput> writeBp95d(const Toolpath& toolpath, const SourceFile* source,
                                     const PointWriteOptions& request, Diagnostics& diags) {
  std::optional<PointOutput> p = emitPoints(toolpath, source, request.profile, request.request, diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request);
}

std::optional<EmitOutput> writePoints4(const Toolpath& toolpath, const SourceFile* source,
                                       const PointWriteOptions& request, Diagnostics& diags) {
  std::optional<PointOutput> p =
      emitPoints4(toolpath, source, request.profile, request.request, request.relativeUv, diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request, true);
}

}  // namespace kerf::converter
