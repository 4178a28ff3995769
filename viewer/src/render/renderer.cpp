// The OpenGL 3.3 renderer (renderer.h).
// Sections: 1. shader programs  2. OffscreenTarget  3. buffers  4. render passes  5. overlay and triad
#include "kerf/render/renderer.h"

#include "kerf/render/gl.h"
#include "shaders.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace kerf::render {

namespace {

// ---- 1. shader programs -------------------------------------------------------------------

unsigned compileStage(GLenum stage, const char* source, std::string& error) {
  const GlApi& g = gl();
  const unsigned shader = g.CreateShader(stage);
  g.ShaderSource(shader, 1, &source, nullptr);
  g.CompileShader(shader);
  GLint ok = 0;
  g.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    g.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    error = std::string("shader does not compile: ") + log;
    g.DeleteShader(shader);
    return 0;
  }
  return shader;
}

unsigned linkProgram(const char* vert, const char* geom, const char* frag, std::string& error) {
  const GlApi& g = gl();
  const unsigned v = compileStage(GL_VERTEX_SHADER, vert, error);
  const unsigned gs = geom ? compileStage(GL_GEOMETRY_SHADER, geom, error) : 0;
  const unsigned f = compileStage(GL_FRAGMENT_SHADER, frag, error);
  unsigned program = 0;
  if (v && f && (geom == nullptr || gs)) {
    program = g.CreateProgram();
    g.AttachShader(program, v);
    if (gs) g.AttachShader(program, gs);
    g.AttachShader(program, f);
    g.LinkProgram(program);
    GLint ok = 0;
    g.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      g.GetProgramInfoLog(program, sizeof log, nullptr, log);
      error = std::string("shaders do not link: ") + log;
      g.DeleteProgram(program);
      program = 0;
    }
  }
  for (unsigned s : {v, gs, f})
    if (s) g.DeleteShader(s);
  return program;
}

int uniform(unsigned program, const char* name) { return gl().GetUniformLocation(program, name); }

struct MarkerVertex {
  std::array<float, 3> position;
  std::uint32_t colour;
  float size;
};

constexpr std::uint32_t kSelectionColour = rgba(255, 200, 0);
constexpr std::uint32_t kStartColour = rgba(30, 170, 60);

}  // namespace

// ---- 2. OffscreenTarget ---------------------------------------------------------------------

OffscreenTarget::~OffscreenTarget() { release(); }

void OffscreenTarget::release() {
  if (gl().DeleteFramebuffers == nullptr) return;
  const GlApi& g = gl();
  if (msFbo_) g.DeleteFramebuffers(1, &msFbo_);
  if (fbo_) g.DeleteFramebuffers(1, &fbo_);
  for (unsigned* rb : {&msColour_, &msDepth_, &colour_})
    if (*rb) g.DeleteRenderbuffers(1, rb);
  msFbo_ = fbo_ = msColour_ = msDepth_ = colour_ = 0;
}

bool OffscreenTarget::create(int width, int height, int samples, std::string& error) {
  release();
  const GlApi& g = gl();
  GLint maxSamples = 1;
  g.GetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  samples_ = std::clamp(samples, 1, std::max(1, maxSamples));
  width_ = width;
  height_ = height;
  const GLsizei s = samples_ > 1 ? samples_ : 0;
  g.GenRenderbuffers(1, &msColour_);
  g.BindRenderbuffer(GL_RENDERBUFFER, msColour_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, s, GL_RGBA8, width, height);
  g.GenRenderbuffers(1, &msDepth_);
  g.BindRenderbuffer(GL_RENDERBUFFER, msDepth_);
  g.RenderbufferStorageMultisample(GL_RENDERBUFFER, s, GL_DEPTH_COMPONENT24, width, height);
  g.GenFramebuffers(1, &msFbo_);
  g.BindFramebuffer(GL_FRAMEBUFFER, msFbo_);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColour_);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth_);
  if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the offscreen framebuffer (" + std::to_string(width) + "x" + std::to_string(height) + ", " +
            std::to_string(samples_) + " samples) is not complete";
    return false;
  }
  g.GenRenderbuffers(1, &colour_);
  g.BindRenderbuffer(GL_RENDERBUFFER, colour_);
  g.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  g.GenFramebuffers(1, &fbo_);
  g.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  if (g.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the resolve framebuffer is not complete";
    return false;
  }
  g.BindFramebuffer(GL_FRAMEBUFFER, msFbo_);
  return true;
}

void OffscreenTarget::bind() const { gl().BindFramebuffer(GL_FRAMEBUFFER, msFbo_); }

void OffscreenTarget::resolveTo(unsigned framebuffer, int x, int y) const {
  const GlApi& g = gl();
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_);
  g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  g.BlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  g.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

std::vector<std::uint8_t> OffscreenTarget::readRgba() const {
  resolveTo(fbo_);
  gl().BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  return readFramebufferRgba(width_, height_);
}

std::vector<std::uint8_t> readFramebufferRgba(int width, int height) {
  const GlApi& g = gl();
  const auto rowBytes = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> bottomUp(rowBytes * static_cast<std::size_t>(height));
  g.PixelStorei(GL_PACK_ALIGNMENT, 1);
  g.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  std::vector<std::uint8_t> topDown(bottomUp.size());
  for (int y = 0; y < height; ++y)
    std::copy_n(bottomUp.data() + static_cast<std::size_t>(height - 1 - y) * rowBytes, rowBytes,
                topDown.data() + static_cast<std::size_t>(y) * rowBytes);
  return topDown;
}

// ---- 3. buffers -----------------------------------------------------------------------------

Renderer::~Renderer() {
  if (gl().DeleteProgram == nullptr) return;
  releaseBuffers();
  const GlApi& g = gl();
  for (unsigned p : {surfaceProgram_, lineProgram_, markerProgram_, overlayProgram_})
    if (p) g.DeleteProgram(p);
  if (overlayEbo_) g.DeleteBuffers(1, &overlayEbo_);
  if (overlayTexture_) g.DeleteTextures(1, &overlayTexture_);
  for (Buffer* b : {&extra_, &triad_, &overlay_, &construction_, &constructionDashed_, &constructionDots_}) {
    if (b->vbo) g.DeleteBuffers(1, &b->vbo);
    if (b->ebo) g.DeleteBuffers(1, &b->ebo);
    if (b->vao) g.DeleteVertexArrays(1, &b->vao);
  }
}

bool Renderer::init(std::string& error) {
  using namespace shaders;
  surfaceProgram_ = linkProgram(kSurfaceVert, nullptr, kSurfaceFrag, error);
  if (!surfaceProgram_) return false;
  lineProgram_ = linkProgram(kLinesVert, kLinesGeom, kLinesFrag, error);
  if (!lineProgram_) return false;
  markerProgram_ = linkProgram(kMarkerVert, nullptr, kMarkerFrag, error);
  if (!markerProgram_) return false;
  overlayProgram_ = linkProgram(kOverlayVert, nullptr, kOverlayFrag, error);
  if (!overlayProgram_) return false;
  const GlApi& g = gl();
  // The triad: unit arrows along x (red), y (green), z (blue).
  const std::vector<LineVertex> triad = {{{0, 0, 0}, rgba(210, 40, 40)}, {{1, 0, 0}, rgba(210, 40, 40)},
                                         {{0, 0, 0}, rgba(40, 160, 40)}, {{0, 1, 0}, rgba(40, 160, 40)},
                                         {{0, 0, 0}, rgba(40, 70, 220)}, {{0, 0, 1}, rgba(40, 70, 220)}};
  setExtraLines(triad, 2.0f);
  std::swap(triad_, extra_);
  setExtraLines({}, 3.0f);
  g.GenVertexArrays(1, &overlay_.vao);
  g.GenBuffers(1, &overlay_.vbo);
  g.GenBuffers(1, &overlayEbo_);
  g.BindVertexArray(overlay_.vao);
  g.BindBuffer(GL_ARRAY_BUFFER, overlay_.vbo);
  g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, overlayEbo_);
  constexpr auto stride = static_cast<GLsizei>(sizeof(OverlayVertex));
  g.EnableVertexAttribArray(0);
  g.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(OverlayVertex, x)));
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(OverlayVertex, u)));
  g.EnableVertexAttribArray(2);
  g.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                        reinterpret_cast<void*>(offsetof(OverlayVertex, colour)));
  g.BindVertexArray(0);
  // A white texel until the caller gives a font atlas, so untextured shapes still draw.
  const std::uint8_t white[4] = {255, 255, 255, 255};
  setOverlayTexture(1, 1, white);
  return true;
}

void Renderer::releaseBuffers() {
  const GlApi& g = gl();
  for (Buffer* b :
       {&surface_, &lower_, &upper_, &generators_, &rapids_, &reference_, &deviation_, &guides_, &markers_}) {
    if (b->vbo) g.DeleteBuffers(1, &b->vbo);
    if (b->ebo) g.DeleteBuffers(1, &b->ebo);
    if (b->vao) g.DeleteVertexArrays(1, &b->vao);
    *b = Buffer{};
  }
}

namespace {

template <typename Vertex>
void upload(unsigned& vao, unsigned& vbo, const std::vector<Vertex>& data) {
  const GlApi& g = gl();
  if (!vao) g.GenVertexArrays(1, &vao);
  if (!vbo) g.GenBuffers(1, &vbo);
  g.BindVertexArray(vao);
  g.BindBuffer(GL_ARRAY_BUFFER, vbo);
  g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(Vertex)), data.data(), GL_STATIC_DRAW);
}

void lineLayout() {
  const GlApi& g = gl();
  constexpr auto stride = static_cast<GLsizei>(sizeof(LineVertex));
  g.EnableVertexAttribArray(0);
  g.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LineVertex, position)));
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(offsetof(LineVertex, colour)));
}

void markerLayout() {
  const GlApi& g = gl();
  constexpr auto stride = static_cast<GLsizei>(sizeof(MarkerVertex));
  g.EnableVertexAttribArray(0);
  g.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MarkerVertex, position)));
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                        reinterpret_cast<void*>(offsetof(MarkerVertex, colour)));
  g.EnableVertexAttribArray(2);
  g.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MarkerVertex, size)));
}

MarkerVertex markerVertex(const Marker& m) {
  return {{static_cast<float>(m.position.x()), static_cast<float>(m.position.y()), static_cast<float>(m.position.z())},
          m.colour,
          m.sizePixels};
}

}  // namespace

void Renderer::setScene(const Scene& scene) {
  releaseBuffers();
  const GlApi& g = gl();
  upload(surface_.vao, surface_.vbo, scene.surface);
  g.GenBuffers(1, &surface_.ebo);
  g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, surface_.ebo);  // the vertex array keeps this binding
  g.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(scene.surfaceIndices.size() * sizeof(std::uint32_t)),
               scene.surfaceIndices.data(), GL_STATIC_DRAW);
  surface_.count = scene.surfaceIndices.size();
  constexpr auto stride = static_cast<GLsizei>(sizeof(SurfaceVertex));
  g.EnableVertexAttribArray(0);
  g.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(SurfaceVertex, position)));
  g.EnableVertexAttribArray(1);
  g.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(SurfaceVertex, normal)));
  g.EnableVertexAttribArray(2);
  g.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(SurfaceVertex, slopeDegrees)));
  g.EnableVertexAttribArray(3);
  g.VertexAttribIPointer(3, 1, GL_UNSIGNED_INT, stride, reinterpret_cast<void*>(offsetof(SurfaceVertex, flags)));
  const std::pair<Buffer*, const LineSet*> sets[] = {{&lower_, &scene.lower},           {&upper_, &scene.upper},
                                                     {&generators_, &scene.generators}, {&rapids_, &scene.rapids},
                                                     {&reference_, &scene.reference},   {&deviation_, &scene.deviation},
                                                     {&guides_, &scene.guides}};
  for (const auto& [buffer, set] : sets) {
    upload(buffer->vao, buffer->vbo, set->vertices);
    buffer->count = set->vertices.size();
    lineLayout();
  }
  lowerFirst_ = scene.lower.moveFirst;
  upperFirst_ = scene.upper.moveFirst;
  std::vector<MarkerVertex> markers;
  for (const Marker& m : scene.findings) markers.push_back(markerVertex(m));
  findingMarkers_ = markers.size();
  markers.push_back(
      {{static_cast<float>(scene.start.x()), static_cast<float>(scene.start.y()), static_cast<float>(scene.start.z())},
       kStartColour,
       9.0f});
  upload(markers_.vao, markers_.vbo, markers);
  markers_.count = markers.size();
  markerLayout();
  g.BindVertexArray(0);
  slopeMin_ = scene.minSlopeDegrees;
  slopeMax_ = scene.maxSlopeDegrees;
}

void Renderer::setConstruction(const ConstructionScene& construction) {
  for (const auto& [buffer, set] :
       {std::pair{&construction_, &construction.lines}, std::pair{&constructionDashed_, &construction.dashed}}) {
    upload(buffer->vao, buffer->vbo, set->vertices);
    lineLayout();
    buffer->count = set->vertices.size();
  }
  std::vector<MarkerVertex> dots;
  for (const Marker& m : construction.points) dots.push_back(markerVertex(m));
  upload(constructionDots_.vao, constructionDots_.vbo, dots);
  markerLayout();
  constructionDots_.count = dots.size();
  gl().BindVertexArray(0);
}

void Renderer::setExtraLines(const std::vector<LineVertex>& lines, float width) {
  upload(extra_.vao, extra_.vbo, lines);
  lineLayout();
  gl().BindVertexArray(0);
  extra_.count = lines.size();
  extraWidth_ = width;
}

void Renderer::setOverlayTexture(int width, int height, const std::uint8_t* pixels) {
  const GlApi& g = gl();
  if (!overlayTexture_) g.GenTextures(1, &overlayTexture_);
  g.BindTexture(GL_TEXTURE_2D, overlayTexture_);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  g.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
}

// ---- 4. render passes -----------------------------------------------------------------------

void Renderer::drawLines(const Buffer& b, std::size_t first, std::size_t count, const Eigen::Matrix4f& viewProj,
                         float width, float dash, int widthPx, int heightPx, const float* colourOverride) {
  if (count == 0) return;
  const GlApi& g = gl();
  g.UseProgram(lineProgram_);
  g.UniformMatrix4fv(uniform(lineProgram_, "uViewProjection"), 1, GL_FALSE, viewProj.data());
  g.Uniform2f(uniform(lineProgram_, "uViewport"), static_cast<float>(widthPx), static_cast<float>(heightPx));
  g.Uniform1f(uniform(lineProgram_, "uWidth"), width);
  g.Uniform1f(uniform(lineProgram_, "uDash"), dash);
  if (colourOverride)
    g.Uniform4f(uniform(lineProgram_, "uColourOverride"), colourOverride[0], colourOverride[1], colourOverride[2],
                colourOverride[3]);
  else
    g.Uniform4f(uniform(lineProgram_, "uColourOverride"), 0, 0, 0, 0);
  g.BindVertexArray(b.vao);
  for (std::size_t at = 0; at < count; at += drawChunk_ * 2) {
    if (at > 0) g.Finish();
    g.DrawArrays(GL_LINES, static_cast<GLint>(first + at), static_cast<GLsizei>(std::min(count - at, drawChunk_ * 2)));
  }
}

/// The cut surface, pushed back a little so the contours drawn over it win the depth test: its
/// colours by slope or pass, the findings' moves tinted; in chunks of drawChunk_ triangles.
void Renderer::drawSurface(const RenderOptions& options, const Eigen::Matrix4f& view, const Eigen::Matrix4f& viewProj) {
  const GlApi& g = gl();
  g.Enable(GL_POLYGON_OFFSET_FILL);
  g.PolygonOffset(1.0f, 1.0f);
  g.UseProgram(surfaceProgram_);
  g.UniformMatrix4fv(uniform(surfaceProgram_, "uViewProjection"), 1, GL_FALSE, viewProj.data());
  g.UniformMatrix4fv(uniform(surfaceProgram_, "uView"), 1, GL_FALSE, view.data());
  g.Uniform3f(uniform(surfaceProgram_, "uBaseColour"), 0.72f, 0.78f, 0.86f);
  g.Uniform1i(uniform(surfaceProgram_, "uColourBySlope"), options.colourBySlope ? 1 : 0);
  g.Uniform1i(uniform(surfaceProgram_, "uColourByPass"), options.colourByPass ? 1 : 0);
  for (std::size_t k = 0; k < kPassColours; ++k) {
    const std::uint32_t c = passColour(k + 1);
    const std::string name = "uPassColours[" + std::to_string(k) + "]";
    g.Uniform3f(uniform(surfaceProgram_, name.c_str()), static_cast<float>(c & 0xFF) / 255.0f,
                static_cast<float>((c >> 8) & 0xFF) / 255.0f, static_cast<float>((c >> 16) & 0xFF) / 255.0f);
  }
  g.Uniform2f(uniform(surfaceProgram_, "uSlopeRange"), static_cast<float>(slopeMin_), static_cast<float>(slopeMax_));
  g.Uniform1i(uniform(surfaceProgram_, "uHighlight"), options.highlightFindings ? 1 : 0);
  g.BindVertexArray(surface_.vao);
  for (std::size_t at = 0; at < surface_.count; at += drawChunk_ * 3) {
    if (at > 0) g.Finish();
    g.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(std::min<std::size_t>(surface_.count - at, drawChunk_ * 3)),
                   GL_UNSIGNED_INT, reinterpret_cast<const void*>(at * sizeof(std::uint32_t)));
  }
  g.Disable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::render(const Camera& camera, const RenderOptions& options, int width, int height) {
  const GlApi& g = gl();
  drawChunk_ = std::max<std::size_t>(1, options.drawChunk);
  g.Viewport(0, 0, width, height);
  const std::uint32_t bg = options.background;
  g.ClearColor(static_cast<float>(bg & 0xFF) / 255.0f, static_cast<float>((bg >> 8) & 0xFF) / 255.0f,
               static_cast<float>((bg >> 16) & 0xFF) / 255.0f, 1.0f);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  g.Disable(GL_SCISSOR_TEST);
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LEQUAL);
  g.DepthMask(GL_TRUE);
  g.Disable(GL_CULL_FACE);
  const double aspect = static_cast<double>(width) / std::max(1, height);
  const Eigen::Matrix4f view = camera.viewMatrix();
  const Eigen::Matrix4f viewProj = camera.projectionMatrix(aspect) * view;

  if (options.surface && surface_.count) drawSurface(options, view, viewProj);

  g.Enable(GL_BLEND);
  g.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const float w = options.lineWidth;
  if (options.generators) drawLines(generators_, 0, generators_.count, viewProj, 1.0f, 0.0f, width, height, nullptr);
  if (options.rapids) drawLines(rapids_, 0, rapids_.count, viewProj, 1.2f, 5.0f, width, height, nullptr);
  if (options.reference && reference_.count)
    drawLines(reference_, 0, reference_.count, viewProj, std::max(1.0f, 0.75f * options.lineWidth), 4.0f, width, height,
              nullptr);
  if (options.contours) {
    drawLines(lower_, 0, lower_.count, viewProj, w, 0.0f, width, height, nullptr);
    drawLines(upper_, 0, upper_.count, viewProj, w, 0.0f, width, height, nullptr);
  }
  if (guides_.count)
    drawLines(guides_, 0, guides_.count, viewProj, std::max(1.0f, 0.75f * w), 0.0f, width, height, nullptr);
  // The part edge in its deviation's colours, over the contours (--color-by deviation).
  if (deviation_.count) drawLines(deviation_, 0, deviation_.count, viewProj, 2.0f * w, 0.0f, width, height, nullptr);
  g.Disable(GL_DEPTH_TEST);
  if (options.selectedMove && *options.selectedMove + 1 < lowerFirst_.size()) {
    const std::size_t m = *options.selectedMove;
    const float yellow[4] = {static_cast<float>(kSelectionColour & 0xFF) / 255.0f,
                             static_cast<float>((kSelectionColour >> 8) & 0xFF) / 255.0f,
                             static_cast<float>((kSelectionColour >> 16) & 0xFF) / 255.0f, 1.0f};
    drawLines(lower_, lowerFirst_[m], lowerFirst_[m + 1] - lowerFirst_[m], viewProj, w * 2.5f, 0, width, height,
              yellow);
    drawLines(upper_, upperFirst_[m], upperFirst_[m + 1] - upperFirst_[m], viewProj, w * 2.5f, 0, width, height,
              yellow);
  }
  drawLines(extra_, 0, extra_.count, viewProj, extraWidth_, 0.0f, width, height, nullptr);
  drawConstruction(viewProj, width, height);  // the selected block's, over everything

  if (options.markers && markers_.count) {
    g.Enable(GL_PROGRAM_POINT_SIZE);
    g.UseProgram(markerProgram_);
    g.UniformMatrix4fv(uniform(markerProgram_, "uViewProjection"), 1, GL_FALSE, viewProj.data());
    g.Uniform1f(uniform(markerProgram_, "uScale"), options.highlightFindings ? 1.5f : 1.0f);
    g.BindVertexArray(markers_.vao);
    // The start point first, so findings at the start stay visible on top of it.
    g.DrawArrays(GL_POINTS, static_cast<GLint>(findingMarkers_), 1);
    g.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(findingMarkers_));
  }

  if (options.triad) {
    const TriadLayout t = triadLayout(camera, height);
    // Rotation only, scaled so a unit arrow is as long as in triadLayout, placed at its origin.
    Camera c = camera;
    c.target = {0, 0, 0};
    c.halfHeight = 0.5 * height / (0.09 * height);
    c.depth = 2.0;
    Eigen::Matrix4f m = c.projectionMatrix(aspect) * c.viewMatrix();
    Eigen::Matrix4f shift = Eigen::Matrix4f::Identity();
    shift(0, 3) = static_cast<float>(t.origin.x() / width * 2.0 - 1.0);
    shift(1, 3) = static_cast<float>(1.0 - t.origin.y() / height * 2.0);
    m = shift * m;
    drawLines(triad_, 0, triad_.count, m, 2.0f, 0.0f, width, height, nullptr);
  }
  g.Disable(GL_BLEND);
  g.BindVertexArray(0);
}

void Renderer::drawConstruction(const Eigen::Matrix4f& viewProj, int width, int height) {
  const GlApi& g = gl();
  if (constructionDashed_.count)
    drawLines(constructionDashed_, 0, constructionDashed_.count, viewProj, 1.5f, 5.0f, width, height, nullptr);
  if (construction_.count)
    drawLines(construction_, 0, construction_.count, viewProj, 2.0f, 0.0f, width, height, nullptr);
  if (constructionDots_.count) {
    g.Enable(GL_PROGRAM_POINT_SIZE);
    g.UseProgram(markerProgram_);
    g.UniformMatrix4fv(uniform(markerProgram_, "uViewProjection"), 1, GL_FALSE, viewProj.data());
    g.Uniform1f(uniform(markerProgram_, "uScale"), 1.0f);
    g.BindVertexArray(constructionDots_.vao);
    g.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(constructionDots_.count));
  }
}

TriadLayout triadLayout(const Camera& camera, int height) {
  TriadLayout t;
  const double arm = 0.09 * height;  // pixels per unit arrow
  t.origin = {arm * 1.3, height - arm * 1.3};
  const geometry::Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    t.tips[i] = t.origin + arm * Eigen::Vector2d(axes[i].dot(camera.right()), -axes[i].dot(camera.up()));
  return t;
}

Camera clearOfTriad(Camera camera, const geometry::Vec3& boxMin, const geometry::Vec3& boxMax, int width, int height) {
  // The triad's square: its origin 1.3 arms in, an arm long, and the axis letters past the tips.
  const double corner = 2.3 * 0.09 * height + 14.0;
  double left = width, bottom = 0;
  for (int i = 0; i < 8; ++i) {
    const geometry::Vec3 p{(i & 1) ? boxMax.x() : boxMin.x(), (i & 2) ? boxMax.y() : boxMin.y(),
                           (i & 4) ? boxMax.z() : boxMin.z()};
    const Eigen::Vector2d q = camera.project(p, width, height);
    left = std::min(left, q.x());
    bottom = std::max(bottom, q.y());
  }
  if (left >= corner || bottom <= height - corner) return camera;
  const double cx = 0.5 * width, cy = 0.5 * height;
  // Zoomed by s about the centre, the box's left edge is at cx - s (cx - left): clear of the
  // corner in x or in y, whichever needs less.
  const double sx = cx - left > 0 ? (cx - corner) / (cx - left) : 1.0;
  const double sy = bottom - cy > 0 ? (cy - corner) / (bottom - cy) : 1.0;
  const double s = std::clamp(std::max(sx, sy), 0.6, 1.0);
  camera.halfHeight /= s;
  return camera;
}

// ---- 5. overlay and triad -------------------------------------------------------------------

void Renderer::drawOverlay(const OverlayDrawData& data, int width, int height) {
  if (data.commands.empty()) return;
  const GlApi& g = gl();
  g.Viewport(0, 0, width, height);
  g.Enable(GL_BLEND);
  g.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  g.Disable(GL_DEPTH_TEST);
  g.Disable(GL_CULL_FACE);
  g.Enable(GL_SCISSOR_TEST);
  g.UseProgram(overlayProgram_);
  g.Uniform2f(uniform(overlayProgram_, "uScreen"), static_cast<float>(width), static_cast<float>(height));
  g.Uniform1i(uniform(overlayProgram_, "uTexture"), 0);
  g.ActiveTexture(GL_TEXTURE0);
  g.BindTexture(GL_TEXTURE_2D, overlayTexture_);
  g.BindVertexArray(overlay_.vao);
  g.BindBuffer(GL_ARRAY_BUFFER, overlay_.vbo);
  g.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.vertices.size() * sizeof(OverlayVertex)),
               data.vertices.data(), GL_STREAM_DRAW);
  g.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, overlayEbo_);
  g.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
               data.indices.data(), GL_STREAM_DRAW);
  for (const OverlayCommand& c : data.commands) {
    const auto x0 = static_cast<GLint>(std::max(0.0f, c.clip[0]));
    const auto y0 = static_cast<GLint>(std::max(0.0f, c.clip[1]));
    const auto x1 = static_cast<GLint>(std::min(static_cast<float>(width), c.clip[2]));
    const auto y1 = static_cast<GLint>(std::min(static_cast<float>(height), c.clip[3]));
    if (x1 <= x0 || y1 <= y0 || c.indexCount == 0) continue;
    g.Scissor(x0, height - y1, x1 - x0, y1 - y0);
    g.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(c.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(static_cast<std::size_t>(c.firstIndex) * sizeof(std::uint32_t)));
  }
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_BLEND);
  g.BindVertexArray(0);
}

}  // namespace kerf::render
