// A headless picture of a scene, context to PNG bytes: what `kerf render` and the render
// benchmark run.
#pragma once

#include "kerf/headless/context.h"
#include "kerf/render/renderer.h"
#include "kerf/render/scene.h"
#include "ui/overlay.h"

#include <string>

namespace kerf::ui {

struct PictureRequest {
  render::View view = render::View::Iso;
  int width = 800, height = 600;
  int samples = 4;  ///< multisampling; clamped to what the context has
  render::RenderOptions options;
  Annotation annotation;
  headless::Backend backend = headless::Backend::Auto;
};

struct PictureResult {
  std::string png;      ///< empty on failure
  std::string error;    ///< why, when png is empty
  std::string context;  ///< the context's description
  double contextSeconds = 0, uploadSeconds = 0, drawSeconds = 0, encodeSeconds = 0;
};

PictureResult renderPicture(const render::Scene& scene, const PictureRequest& request);

}  // namespace kerf::ui
