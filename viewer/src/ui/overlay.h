// The picture's annotations (title, slope legend, scale bar, finding labels, triad letters) drawn
// with Dear ImGui's draw lists, and the conversion of ImGui's draw data for kerf::render.
#pragma once

#include "kerf/render/camera.h"
#include "kerf/render/overlay.h"
#include "kerf/render/renderer.h"
#include "kerf/render/scene.h"

#include <string>
#include <vector>

struct ImDrawList;
struct ImDrawData;
struct ImGuiContext;

namespace kerf::ui {

struct Annotation {
  std::string title;     ///< first line: the file
  std::string subtitle;  ///< second line: dialect, moves, verdict
  bool legend = false;   ///< the slope colour ramp with its range
  /// Colour by pass: one legend entry a pass number, "pass 1 (rough)", "pass 2", ... (their colours
  /// are render::passColour(1), (2), ...). Empty: no pass legend.
  std::vector<std::string> passLegend;
  /// --color-by deviation: the ramp from 0 to this many µm (SceneOptions::deviationScale), with a
  /// mark at the tolerance. 0: no deviation legend.
  double deviationScaleUm = 0.0;
  double toleranceUm = 0.0;
  bool labels = false;  ///< finding labels next to their markers
  /// The errors and warnings of the program: those not labelled (no place in the picture, or a
  /// label that would cover another) are counted under the title, "+6 more".
  std::size_t findings = 0;
  /// A block's construction (`--explain-line`, the window's selected block): its labels and caption.
  /// Null: none.
  const render::ConstructionScene* construction = nullptr;
};

/// Draws the annotations of `scene` seen through `camera` into `list`, for a width x height image.
void drawAnnotations(ImDrawList& list, const render::Scene& scene, const render::Camera& camera,
                     const render::RenderOptions& options, const Annotation& annotation, int width, int height);

/// ImGui's draw data as kerf::render overlay data (one index space, clip rectangles kept).
render::OverlayDrawData convertDrawData(const ImDrawData& data);

/// A private ImGui context for one headless picture: fonts built, nothing else.
class HeadlessOverlay {
 public:
  HeadlessOverlay();
  ~HeadlessOverlay();
  HeadlessOverlay(const HeadlessOverlay&) = delete;
  HeadlessOverlay& operator=(const HeadlessOverlay&) = delete;
  /// Uploads the font atlas to the renderer (once per renderer).
  void uploadFont(render::Renderer& renderer);
  /// One frame of annotations, converted.
  render::OverlayDrawData frame(const render::Scene& scene, const render::Camera& camera,
                                const render::RenderOptions& options, const Annotation& annotation, int width,
                                int height);

 private:
  ImGuiContext* context_ = nullptr;
};

/// The 1-2-5 length nearest below `maxLength` (mm), for scale bars.
double niceLength(double maxLength);

}  // namespace kerf::ui
