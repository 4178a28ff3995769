// Sections: 1. arrays as base 64  2. the scene  3. the program, its findings and passes
//           4. the constructions  5. the page
// The 3D page (part_page.h). The data is one JSON text in a <script type="application/json">
// (scriptJson), read by web/part_page.js; numeric arrays travel as base-64 little-endian bytes.
#include "kerf/export/part_page.h"

#include "kerf/converter/check/drawing_check.h"
#include "kerf/converter/interpret/dialect.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/construction.h"
#include "kerf/converter/report/html.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/export/mesh_export.h"
#include "kerf/render/construction_scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace kerf::exporter {

namespace web {
extern const char* const kThreeMinJs;
extern const char* const kOrbitcontrolsJs;
extern const char* const kPartPageJs;
extern const char* const kPartPageCss;
}  // namespace web

namespace {

using nlohmann::json;

// ---- 1. arrays as base 64 -----------------------------------------------------------------------

/// The values' bytes, little-endian (what a typed array on every current browser reads).
template <typename T>
std::string packed(std::span<const T> values) {
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian arrays");
  std::vector<std::uint8_t> bytes(values.size_bytes());
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return converter::base64(bytes);
}
template <typename T>
std::string packed(const std::vector<T>& values) {
  return packed(std::span<const T>(values));
}

/// A line set as {positions: float32 x3, colours: uint32 ABGR, moveFirst: uint32}.
json lineSetData(const render::LineSet& set) {
  std::vector<float> positions;
  std::vector<std::uint32_t> colours;
  positions.reserve(set.vertices.size() * 3);
  colours.reserve(set.vertices.size());
  for (const render::LineVertex& v : set.vertices) {
    positions.insert(positions.end(), v.position.begin(), v.position.end());
    colours.push_back(v.colour);
  }
  return {{"positions", packed(positions)}, {"colours", packed(colours)}, {"moveFirst", packed(set.moveFirst)}};
}

json point(const geometry::Vec3& p) { return json::array({p.x(), p.y(), p.z()}); }

// ---- 2. the scene -------------------------------------------------------------------------------

/// The scene the page shows: at the asked tolerance, or, when that would pass the budget's
/// triangles, at the coarse level of the page's view. The exact mesh stops at the budget (meshing
/// stops there, not after a million triangles thrown away).
render::Scene pageScene(const converter::Pipeline& p, std::span<const converter::Diagnostic> shown,
                        const PartPageOptions& o, PartPage& page) {
  const std::vector<geometry::Segment> reference = converter::referenceGeometry(p);
  render::SceneOptions exact = o.scene;
  exact.maxTriangles = std::min(exact.maxTriangles, o.triangleBudget);
  render::Scene scene = render::buildScene(p.toolpath, shown, exact, reference);
  if (scene.truncated && o.triangleBudget < o.scene.maxTriangles) {
    const geometry::Vec3 size = scene.boundsMax - scene.boundsMin;
    const double mmPerPixel = std::max({size.x(), size.y(), size.z(), 1e-3}) / o.viewPixels;
    scene = render::buildScene(p.toolpath, shown, render::coarseSceneOptions(o.scene, mmPerPixel), reference);
    page.coarse = true;
  }
  page.triangles = scene.triangles();
  page.truncated = scene.truncated;
  return scene;
}

/// The surface: positions, each vertex's slope and move, the triangles.
json surfaceData(const render::Scene& scene) {
  std::vector<float> positions, slopes;
  std::vector<std::uint32_t> moves(scene.surface.size(), 0);
  positions.reserve(scene.surface.size() * 3);
  slopes.reserve(scene.surface.size());
  for (const render::SurfaceVertex& v : scene.surface) {
    positions.insert(positions.end(), v.position.begin(), v.position.end());
    slopes.push_back(v.slopeDegrees);
  }
  for (std::size_t t = 0; t < scene.triangleMove.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) moves[scene.surfaceIndices[3 * t + k]] = scene.triangleMove[t];
  return {{"positions", packed(positions)},
          {"slope", packed(slopes)},
          {"move", packed(moves)},
          {"index", packed(scene.surfaceIndices)}};
}

/// The colours the page takes from the renderer: the ramp (slope, deviation) at 64 stops, the
/// passes' colours.
json colourData() {
  json ramp = json::array(), passes = json::array();
  for (int k = 0; k < 64; ++k) ramp.push_back(render::rampColour(k / 63.0));
  for (std::size_t k = 1; k <= render::kPassColours; ++k) passes.push_back(render::passColour(k));
  return {{"ramp", ramp}, {"passes", passes}};
}

json sceneData(const render::Scene& scene, const PartPage& page, const PartPageOptions& o) {
  json lines = json::object();
  const std::pair<const char*, const render::LineSet*> sets[] = {
      {"lower", &scene.lower},   {"upper", &scene.upper},         {"generators", &scene.generators},
      {"rapids", &scene.rapids}, {"reference", &scene.reference}, {"deviation", &scene.deviation},
      {"guides", &scene.guides}};
  for (const auto& [name, set] : sets)
    if (!set->vertices.empty()) lines[name] = lineSetData(*set);
  std::string size = std::to_string(page.triangles) + " triangles";
  if (page.coarse)
    size += ", drawn coarse: the exact surface (at " + converter::formatFixed(o.scene.tolerance, 3) +
            " mm) has more than the page's " + std::to_string(o.triangleBudget) +
            " (--page-triangles); kerf view draws it exact";
  if (page.truncated) size += "; incomplete: the triangle limit was reached";
  return {{"surface", surfaceData(scene)},
          {"lines", lines},
          {"boundsMin", point(scene.boundsMin)},
          {"boundsMax", point(scene.boundsMax)},
          {"taper", scene.taper},
          {"slope", json::array({scene.minSlopeDegrees, scene.maxSlopeDegrees})},
          {"size", size},
          {"colours", colourData()}};
}

// ---- 3. the program, its findings and passes ------------------------------------------------------

json programData(const converter::Pipeline& p) {
  json lines = json::array();
  if (p.source) {
    std::uint32_t count = p.source->lineCount();
    if (count > 0 && p.source->lineText(count).empty()) --count;  // after the last line break: no line
    for (std::uint32_t l = 1; l <= count; ++l) lines.push_back(std::string(p.source->lineText(l)));
  }
  std::vector<std::uint32_t> moveLine;
  moveLine.reserve(p.toolpath.moves.size());
  for (const converter::Move& m : p.toolpath.moves) moveLine.push_back(m.line);
  return {{"lines", lines}, {"moveLine", packed(moveLine)}};
}

json findingsData(const converter::Pipeline& p, std::span<const converter::Diagnostic> shown) {
  json out = json::array();
  for (const converter::Diagnostic& d : shown) {
    json f = {{"severity", converter::severityName(d.severity)},
              {"code", converter::codeName(d.code)},
              {"text", converter::formatDiagnostic(d)}};
    std::uint32_t line = 0;
    if (d.move && *d.move < p.toolpath.moves.size())
      line = p.toolpath.moves[*d.move].line;
    else if (d.source == p.source.get() && d.source && !d.span.isWholeFile())
      line = d.source->locate(d.span.offset).line;
    if (line) f["line"] = line;
    if (d.point) f["point"] = point(*d.point);
    out.push_back(std::move(f));
  }
  return out;
}

json passesData(const converter::Pipeline& p) {
  json out = json::array();
  for (std::size_t c = 0; c < p.structure.contours.size(); ++c) {
    const converter::Contour& contour = p.structure.contours[c];
    for (std::size_t k = 0; k < contour.passes.size(); ++k) {
      const converter::Pass& pass = contour.passes[k];
      out.push_back({{"name", converter::passName(c, k) + ": " + converter::passRole(pass, k) + ", " +
                                  converter::offsetText(pass)},
                     {"pass", k + 1},
                     {"first", pass.first},
                     {"end", pass.end},
                     {"lines", json::array({pass.firstLine, pass.lastLine})}});
    }
  }
  return out;
}

// ---- 4. the constructions -----------------------------------------------------------------------

json markersData(const std::vector<render::Marker>& markers) {
  json out = json::array();
  for (const render::Marker& m : markers)
    out.push_back({{"p", point(m.position)}, {"colour", m.colour}, {"label", m.label}});
  return out;
}

/// A block's construction; its modes as indexes into `sentences` (blocks mostly inherit the same).
json constructionData(const converter::Construction& c, const render::ConstructionScene& drawn,
                      std::vector<std::string>& sentences) {
  json words = json::array();
  for (const converter::WordMeaning& w : c.words) words.push_back(json::array({w.word, w.sets}));
  json key = json::array(), roles = json::array();  // each role once, in the marks' order
  for (const converter::ConstructionMark& m : c.marks) {
    if (!m.label.empty()) key.push_back(m.label);
    const std::string role = converter::markRoleName(m.role);
    if (std::find(roles.begin(), roles.end(), role) == roles.end()) roles.push_back(role);
  }
  json modes = json::array();
  for (const std::string& m : c.modes) {
    const auto at = std::find(sentences.begin(), sentences.end(), m);
    modes.push_back(at - sentences.begin());
    if (at == sentences.end()) sentences.push_back(m);
  }
  return {{"move", c.move},
          {"line", c.line},
          {"block", c.block},
          {"key", key},
          {"roles", roles},
          {"words", words},
          {"modes", modes},
          {"pass", c.pass},
          {"lines", lineSetData(drawn.lines)},
          {"dashed", lineSetData(drawn.dashed)},
          {"points", markersData(drawn.points)},
          {"labels", markersData(drawn.labels)}};
}

/// The constructions of the first move of each line, in order, within the options' budgets:
/// {blocks: [...], sentences: [the modes' sentences]}.
json constructionsData(const converter::Pipeline& p, const render::Scene& scene, const PartPageOptions& o,
                       PartPage& page) {
  json blocks = json::array();
  std::vector<std::string> sentences;
  std::size_t bytes = 0;
  std::uint32_t lastLine = 0;
  const double tolerance = o.scene.lineTolerance > 0 ? o.scene.lineTolerance : o.scene.tolerance;
  for (std::size_t i = 0; p.source && i < p.toolpath.moves.size() && page.constructions < o.constructionBlocks; ++i) {
    const std::uint32_t line = p.toolpath.moves[i].line;
    if (line == 0 || line == lastLine) continue;
    lastLine = line;
    const converter::Construction c =
        converter::constructionOf(*p.source, p.toolpath, &p.structure, o.sampling, i, o.parse);
    const render::ConstructionScene drawn = render::constructionScene(c, scene.planes, tolerance, 0);
    json block = constructionData(c, drawn, sentences);
    bytes += block.dump(-1, ' ', false, json::error_handler_t::replace).size();
    if (bytes > o.constructionBytes) break;
    blocks.push_back(std::move(block));
    ++page.constructions;
  }
  return {{"blocks", std::move(blocks)}, {"sentences", std::move(sentences)}};
}

// ---- 5. the page --------------------------------------------------------------------------------

/// The page's frame: the panels the script fills (no text from the input here but the title).
std::string pageHtml(const std::string& name, const std::string& data, bool scriptFiles) {
  static const std::string_view styles[] = {web::kPartPageCss};
  static const std::string policy = [] {
    std::vector<std::string_view> texts;
    for (const PageScript& s : partPageScripts()) texts.push_back(s.text);
    return converter::contentSecurityPolicy(texts, styles);
  }();
  static const std::string filesPolicy = converter::contentSecurityPolicy({}, styles, true);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"" +
      (scriptFiles ? filesPolicy : policy) +
      "\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      converter::markupText(converter::programTitle(name, " — Kerf")) + "</title>\n<style>" + web::kPartPageCss +
      "</style>\n" +
      "</head>\n<body>\n"
      "<header><h1 id=\"title\">" +
      converter::markupText(name) +
      "</h1><p id=\"subtitle\"></p></header>\n"
      "<main>\n<section id=\"text\" aria-label=\"program\"><div id=\"lines\"></div></section>\n"
      "<section id=\"view\" aria-label=\"part\"><canvas id=\"canvas\"></canvas><div id=\"labels\"></div>"
      "<nav id=\"tools\"></nav><p id=\"size\"></p></section>\n"
      "<aside id=\"side\"><h2>Construction</h2><div id=\"construction\"></div>"
      "<h2>Findings</h2><ol id=\"findings\"></ol><h2>Passes</h2><ul id=\"passes\"></ul></aside>\n"
      "</main>\n"
      "<script type=\"application/json\" id=\"kerf-data\">" +
      data + "</script>\n";
  for (const PageScript& s : partPageScripts())
    html += scriptFiles ? "<script src=\"" + std::string(s.file) + "\"></script>\n"
                        : "<script>" + std::string(s.text) + "</script>\n";
  return html + "</body>\n</html>\n";
}

}  // namespace

std::span<const PageScript> partPageScripts() {
  static const PageScript scripts[] = {{"kerf-three.min.js", web::kThreeMinJs},
                                       {"kerf-orbit-controls.js", web::kOrbitcontrolsJs},
                                       {"kerf-part-page.js", web::kPartPageJs}};
  return scripts;
}

std::string tellingColouring(const converter::Pipeline& p) {
  if (p.comparison) return "deviation";
  if (p.structure.multiPass()) return "pass";
  return p.toolpath.isTaper() ? "slope" : "plain";
}

PartPage partPage(const converter::Pipeline& p, const std::string& name, std::span<const converter::Diagnostic> shown,
                  const PartPageOptions& o) {
  PartPage page;
  const render::Scene scene = pageScene(p, shown, o, page);
  json data = {{"name", name},
               {"dialect", p.toolpath.isTaper() ? converter::dialectName(p.toolpath.dialect) : "2-axis"},
               {"colourBy", o.colourBy.empty() ? tellingColouring(p) : o.colourBy},
               {"scene", sceneData(scene, page, o)},
               {"program", programData(p)},
               {"findings", findingsData(p, shown)},
               {"passes", passesData(p)},
               {"movePass", packed(converter::movePasses(p.structure, p.toolpath.moves.size()))},
               {"constructions", constructionsData(p, scene, o, page)}};
  if (p.comparison) {
    data["moveDeviation"] = packed(moveDeviations(*p.comparison, p.toolpath.moves.size()));
    data["deviationScale"] = o.scene.deviationScale;
    data["tolerance"] = p.comparison->tolerance;
  }
  const std::string text = data.dump(-1, ' ', false, json::error_handler_t::replace);
  page.html = pageHtml(name, converter::scriptJson(text), o.scriptFiles);
  return page;
}

}  // namespace kerf::exporter
