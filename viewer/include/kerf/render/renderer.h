// The OpenGL 3.3 core renderer: draws a Scene and a 2D overlay into the framebuffer that is bound.
// It needs a current context and loadGl() done; it knows nothing of windows, GLFW or ImGui.
//
// Passes, in order: surface (lit; or coloured by slope), contour/generator/rapid lines (widened
// to quads in a geometry shader, rapids dashed), extra lines (the wire in playback, a selection),
// finding and start markers (always on top), the axis triad in the bottom-left corner.
#pragma once

#include "kerf/render/camera.h"
#include "kerf/render/construction_scene.h"
#include "kerf/render/overlay.h"
#include "kerf/render/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::render {

struct RenderOptions {
  bool surface = true;
  bool contours = true;
  bool generators = true;
  bool rapids = true;
  bool reference = true;  ///< the geometry the wire path was made from (Scene::reference), dashed
  bool markers = true;
  bool triad = true;
  bool colourBySlope = false;
  bool colourByPass = false;       ///< the surface in its pass's colour (Scene built with SceneOptions::movePass)
  bool highlightFindings = false;  ///< tint the surface of moves with findings, bigger markers
  float lineWidth = 2.0f;          ///< pixels
  std::uint32_t background = rgba(250, 250, 250);
  std::optional<std::size_t> selectedMove;  ///< drawn again, thick and yellow
  /// Primitives drawn between two waits for the rasteriser (glFinish). llvmpipe bins every
  /// primitive into each 64x64 tile it covers and holds the bins until the scene is drawn, so a part
  /// of long thin walls that cross many tiles needs several times its mesh's memory in one call;
  /// in pieces the same PNG comes out, byte for byte, with the bins bounded. Smaller pieces cost
  /// time (docs/rendering.md). The window draws in one call (window.cpp).
  std::size_t drawChunk = std::size_t{1} << 18;
};

/// An offscreen colour + depth target, multisampled when the context allows.
class OffscreenTarget {
 public:
  OffscreenTarget() = default;
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;
  ~OffscreenTarget();
  /// (Re)creates the buffers; samples is clamped to GL_MAX_SAMPLES (1: no multisampling).
  bool create(int width, int height, int samples, std::string& error);
  void bind() const;
  /// Resolves the samples into `framebuffer` (0: the window), its lower-left corner at (x, y).
  void resolveTo(unsigned framebuffer, int x = 0, int y = 0) const;
  /// RGBA rows top to bottom, after resolving.
  [[nodiscard]] std::vector<std::uint8_t> readRgba() const;
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int samples() const { return samples_; }

 private:
  void release();
  unsigned msFbo_ = 0, msColour_ = 0, msDepth_ = 0;  // drawn into
  unsigned fbo_ = 0, colour_ = 0;                    // resolved
  int width_ = 0, height_ = 0, samples_ = 1;
};

/// RGBA rows top to bottom of the framebuffer bound for reading.
std::vector<std::uint8_t> readFramebufferRgba(int width, int height);

class Renderer {
 public:
  Renderer() = default;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer();

  /// Compiles the shaders (GLSL 330, shaders/). False with the compiler's log in error.
  bool init(std::string& error);
  /// Uploads the scene's buffers; the scene may be dropped afterwards except for what the caller keeps.
  void setScene(const Scene& scene);
  /// A block's construction, drawn over everything each frame until replaced (an empty one: none).
  void setConstruction(const ConstructionScene& construction);
  /// Lines drawn on top of the scene each frame (the wire in playback), width in pixels.
  void setExtraLines(const std::vector<LineVertex>& lines, float width);
  /// The overlay's texture: RGBA, width x height (ImGui's font atlas).
  void setOverlayTexture(int width, int height, const std::uint8_t* rgba);
  /// Draws the scene into the bound framebuffer, viewport width x height.
  void render(const Camera& camera, const RenderOptions& options, int width, int height);
  /// Draws 2D geometry on top (no depth test, blended, scissored per command).
  void drawOverlay(const OverlayDrawData& data, int width, int height);

 private:
  struct Buffer {
    unsigned vao = 0, vbo = 0;
    unsigned ebo = 0;       ///< indices (the surface only)
    std::size_t count = 0;  ///< vertices drawn (indices, with ebo)
  };
  void drawLines(const Buffer& b, std::size_t first, std::size_t count, const Eigen::Matrix4f& viewProj, float width,
                 float dash, int width_px, int height_px, const float* colourOverride);
  void releaseBuffers();
  /// The construction's dashed and solid lines and its dots (setConstruction), depth test off.
  void drawSurface(const RenderOptions& options, const Eigen::Matrix4f& view, const Eigen::Matrix4f& viewProj);
  void drawConstruction(const Eigen::Matrix4f& viewProj, int width, int height);

  unsigned surfaceProgram_ = 0, lineProgram_ = 0, markerProgram_ = 0, overlayProgram_ = 0;
  Buffer surface_, lower_, upper_, generators_, rapids_, reference_, deviation_, guides_, markers_, extra_, triad_,
      overlay_;
  Buffer construction_, constructionDashed_, constructionDots_;
  unsigned overlayEbo_ = 0, overlayTexture_ = 0;
  std::vector<std::uint32_t> lowerFirst_, upperFirst_;
  float extraWidth_ = 3.0f;
  std::size_t findingMarkers_ = 0;
  std::size_t drawChunk_ = RenderOptions{}.drawChunk;  ///< the options' drawChunk during render()
  double slopeMin_ = 0.0, slopeMax_ = 0.0;
};

}  // namespace kerf::render

namespace kerf::render {

/// Where the axis triad's X, Y and Z arrows end, in pixels of an image `height` pixels high (origin
/// top left, the triad in the bottom-left corner), so labels drawn in the overlay sit at the renderer's arrows.
struct TriadLayout {
  Eigen::Vector2d origin;
  std::array<Eigen::Vector2d, 3> tips;
};
TriadLayout triadLayout(const Camera& camera, int height);

/// The camera zoomed out about the picture's centre (at most to 0.6 of its scale) so that the box's
/// outline keeps out of the triad's corner (bottom left), when it would reach into it.
Camera clearOfTriad(Camera camera, const geometry::Vec3& boxMin, const geometry::Vec3& boxMax, int width, int height);

}  // namespace kerf::render
