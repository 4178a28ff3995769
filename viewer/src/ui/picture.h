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

/// Multisampling for a picture: 4x, unless most triangles are smaller than a pixel: the triangles
/// outnumber half the pixels, or they outnumber an eighth of them and (given the pixel's size,
/// mm) the surface's mean triangle covers less than 2x2 pixels: there 4x costs about twice the time
/// under llvmpipe (docs/performance.md) and the surface gains little from it.
int autoSamples(const render::Scene& scene, int width, int height, double mmPerPixel = 0.0);

PictureResult renderPicture(const render::Scene& scene, const PictureRequest& request);

/// The picture's camera for a box (renderPicture fits the scene's bounds the same way).
render::Camera pictureCamera(const geometry::Vec3& lo, const geometry::Vec3& hi, const PictureRequest& request);

/// How long a pixel of the picture is, mm, at the box's fitted zoom: the shortest forced mesh
/// piece worth making (SceneOptions::minForcedPieceLength).
double picturePixelMm(const converter::Toolpath& toolpath, const render::SceneOptions& options,
                      const PictureRequest& request);

}  // namespace kerf::ui
