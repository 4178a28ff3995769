// `kerf view`: the interactive window (GLFW + Dear ImGui). The program text and the 3D part point
// at each other: click a segment to select its block, click a line or a finding to see it.
#pragma once

#include "kerf/converter/check/drawing_check.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"
#include "kerf/render/renderer.h"
#include "kerf/render/scene.h"
#include "ui/overlay.h"

#include <optional>
#include <string>
#include <vector>

namespace kerf::window {

struct WindowRequest {
  const converter::SourceFile* source = nullptr;
  const converter::Toolpath* toolpath = nullptr;
  /// Its contours and passes: a program cut in several passes gets the pass list (show, hide,
  /// select, colour by pass). Null: no list.
  const converter::Structure* structure = nullptr;
  std::vector<converter::Diagnostic> findings;
  std::vector<geometry::Segment> reference;  ///< converter::referenceGeometry: drawn beside the path
  /// The program against --drawing: its elements out of tolerance are listed, each selecting its
  /// nearest block. Null: no drawing.
  const converter::DrawingComparison* comparison = nullptr;
  const converter::DrawingComparison* comparisonUpper = nullptr;  ///< a taper's upper plane (--drawing-upper)
  const render::Scene* scene = nullptr;
  render::SceneOptions sceneOptions;  ///< what `scene` was built with (the coarse level starts from it)
  bool coarseFrames = false;          ///< draw every frame at the coarse level (benchmarks what orbiting costs)
  render::RenderOptions options;
  ui::Annotation annotation;
  double step = 0.1;              ///< initial interpolation step k, mm
  converter::ParseOptions parse;  ///< the machine's: the selected block's words are read with them
  int width = 1280, height = 800;
  std::optional<std::string> screenshot;  ///< write the window as PNG after `frames` frames, then close
  int frames = 0;                         ///< 0: run until closed
  bool benchmark = false;                 ///< print frame times when closing
  std::optional<std::size_t> selectLine;  ///< start with the move on this source line selected
  double playback = -1;                   ///< start the wire at this fraction of the path (< 0: hidden)
  std::vector<std::string> inputs;        ///< every file read: a screenshot may replace none of them
};

/// Runs the window until it is closed (or `frames` are drawn). False with a message when no
/// window can be opened (no display) or the screenshot cannot be written.
bool runWindow(const WindowRequest& request, std::string& error);

}  // namespace kerf::window
