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

int autoSamples(const render::Scene& scene, int width, int height, double mmPerPixel) {
  const std::size_t triangles = scene.triangles();
  if (triangles > static_cast<std::size_t>(width) * static_cast<std::size_t>(height) / 2) return 1;
  // A triangle's area is at least its projected area: a mean under 2x2 pixels is a surface of
  // slivers and specks, whose edges multisampling would smooth little; with more than one
  // triangle to every eight pixels it would also cost much (few triangles cost little either way).
  if (triangles * 8 > static_cast<std::size_t>(width) * static_cast<std::size_t>(height) && mmPerPixel > 0.0 &&
      scene.surfaceArea / static_cast<double>(triangles) < 4.0 * mmPerPixel * mmPerPixel)
    return 1;
  return 4;
}

render::Camera pictureCamera(const geometry::Vec3& lo, const geometry::Vec3& hi, const PictureRequest& request) {
  // A construction's caption takes a band of its own under the title (a line is 13 pixels and 1 apart).
  const std::size_t caption = request.annotation.construction ? request.annotation.construction->caption.size() : 0;
  const int band = kTitleBand + (caption > 0 ? static_cast<int>(caption) * 14 + 8 : 0);
  return render::fitCamera(lo, hi, request.view, request.width, request.height, 0.08,
                           std::min(band, request.height / 2));
}

double picturePixelMm(const converter::Toolpath& toolpath, const render::SceneOptions& options,
                      const PictureRequest& request) {
  geometry::Vec3 lo, hi;
  render::toolpathBounds(toolpath, options.displayHeight, lo, hi);
  if (!lo.allFinite() || !hi.allFinite()) return 0.0;
  return pictureCamera(lo, hi, request).mmPerPixel(request.height);
}

PictureResult renderPicture(const render::Scene& scene, const PictureRequest& request) {
  PictureResult result;
  auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<headless::Context> context = headless::createContext(request.backend, result.error);
  if (!context) return result;
  result.context = context->description();
  render::OffscreenTarget target;
  render::Renderer renderer;
  const render::Camera camera = pictureCamera(scene.boundsMin, scene.boundsMax, request);
  const int samples = request.samples > 0
                          ? request.samples
                          : autoSamples(scene, request.width, request.height, camera.mmPerPixel(request.height));
  if (!renderer.init(result.error) || !target.create(request.width, request.height, samples, result.error))
    return result;
  HeadlessOverlay overlay;
  overlay.uploadFont(renderer);
  result.contextSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  renderer.setScene(scene);
  if (request.annotation.construction) renderer.setConstruction(*request.annotation.construction);
  result.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
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
