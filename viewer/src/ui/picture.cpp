#include "ui/picture.h"

#include "kerf/headless/png.h"
#include "kerf/render/gl.h"

#include <chrono>

namespace kerf::ui {

namespace {
constexpr int kTitleBand = 36;  // pixels: the title and subtitle lines
double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int autoSamples(std::size_t triangles, int width, int height) {
  return triangles > static_cast<std::size_t>(width) * static_cast<std::size_t>(height) / 2 ? 1 : 4;
}

PictureResult renderPicture(const render::Scene& scene, const PictureRequest& request) {
  PictureResult result;
  auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<headless::Context> context = headless::createContext(request.backend, result.error);
  if (!context) return result;
  result.context = context->description();
  render::OffscreenTarget target;
  render::Renderer renderer;
  if (!renderer.init(result.error) ||
      !target.create(
          request.width, request.height,
          request.samples > 0 ? request.samples : autoSamples(scene.triangles(), request.width, request.height),
          result.error))
    return result;
  HeadlessOverlay overlay;
  overlay.uploadFont(renderer);
  result.contextSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  renderer.setScene(scene);
  result.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  const render::Camera camera = render::fitCamera(scene.boundsMin, scene.boundsMax, request.view, request.width,
                                                  request.height, 0.08, kTitleBand);
  target.bind();
  renderer.render(camera, request.options, request.width, request.height);
  renderer.drawOverlay(overlay.frame(scene, camera, request.options, request.annotation, request.width, request.height),
                       request.width, request.height);
  const std::vector<std::uint8_t> pixels = target.readRgba();
  if (const GLenum e = render::gl().GetError(); e != GL_NO_ERROR) {
    result.error = "OpenGL error " + std::to_string(e) + " while drawing";
    return result;
  }
  result.drawSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  result.png = headless::encodePng(pixels, request.width, request.height);
  if (result.png.empty()) result.error = "the PNG could not be encoded";
  result.encodeSeconds = secondsSince(t0);
  return result;
}

}  // namespace kerf::ui
