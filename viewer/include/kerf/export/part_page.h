// `kerf export part.nc -o part.html`: one self-contained HTML file that shows the part in 3D beside
// the program's text and teaches it (docs/teaching.md). The page embeds three.js (Debian's
// libjs-three, compiled in at build time), its own script and style, and the part as data: the
// scene (render/scene.h) as base-64 arrays, the program's lines, the findings, the passes and the
// constructions of its blocks (converter/report/construction.h, drawn by render/construction_scene.h
// as `kerf render --explain-line` draws them). Nothing is fetched: the page works offline, under a
// Content-Security-Policy that allows only its own scripts and style, by hash; everything from the
// input is data, put into the page as text (textContent), never markup.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/pipeline.h"
#include "kerf/geometry/tessellation.h"
#include "kerf/render/scene.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace kerf::exporter {

struct PartPageOptions {
  /// The scene as `kerf render` would build it (tolerance, generators, guides; movePass and the
  /// deviation edge filled by the caller when it has them).
  render::SceneOptions scene;
  geometry::Sampling sampling;    ///< the constructions' step (kerf explain's)
  converter::ParseOptions parse;  ///< how the constructions read a block's words (the machine's)
  /// Above `triangleBudget` triangles the part is sent at the coarse level of a view `viewPixels`
  /// high (render::coarseSceneOptions, the window's while it moves), and the page says so.
  std::size_t triangleBudget = render::kCoarseAboveTriangles;
  double viewPixels = 900.0;
  /// The blocks whose construction the page carries, in the program's order, and the bytes of
  /// data all of them may take; past either, a block's construction is named, not drawn.
  std::size_t constructionBlocks = 4000;
  std::size_t constructionBytes = 4u << 20;
  /// Open in this colouring: "slope", "pass", "deviation" or "plain"; empty: slope for a taper,
  /// pass for a program with several passes, deviation with a drawing, else plain.
  std::string colourBy;
  /// The scripts as files beside the page (partPageScripts), allowed by `script-src 'self'`,
  /// instead of in it: the pages of a report share one copy of three.js.
  bool scriptFiles = false;
};

struct PartPage {
  std::string html;
  std::size_t triangles = 0;      ///< in the page
  bool coarse = false;            ///< at the asked tolerance the part has more than the budget's triangles
  bool truncated = false;         ///< the scene's own limit (SceneOptions::maxTriangles) was reached
  std::size_t constructions = 0;  ///< blocks whose construction the page draws
};

/// A script of the page: the name it has as a file beside the page (PartPageOptions::scriptFiles)
/// and its text.
struct PageScript {
  const char* file;
  std::string_view text;
};
/// The page's scripts in the order it runs them.
std::span<const PageScript> partPageScripts();

/// The colouring that tells most about a program: "deviation" against a drawing, "pass" for
/// several passes, "slope" for a taper, else "plain" (the page opens in it, the report's pictures
/// are drawn in it).
std::string tellingColouring(const converter::Pipeline& pipeline);

/// The page of `pipeline`'s program, named `name`, with the findings `shown` (what kerf check shows
/// for the same options). Never fails: a program with errors gets its page, its errors on it.
PartPage partPage(const converter::Pipeline& pipeline, const std::string& name,
                  std::span<const converter::Diagnostic> shown, const PartPageOptions& options);

}  // namespace kerf::exporter
