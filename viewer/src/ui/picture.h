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
  int samples = 0;  ///< multisampling, clamped to what the context has; 0: autoSamples()
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

/// Multisampling for a picture: 4x, unless the triangles outnumber half the pixels. Then most
/// triangles are smaller than a pixel, 4x costs twice the time under llvmpipe (measured: 1e6
/// triangles at 1024x768, 1.14 s against 0.55 s), and the surface gains little from it.
int autoSamples(std::size_t triangles, int width, int height);

PictureResult renderPicture(const render::Scene& scene, const PictureRequest& request);

}  // namespace kerf::ui
