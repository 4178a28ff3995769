// Index: GL loading through GLFW; the window's state; picking; panels; the frame loop.
#include "window/window.h"

#include "cli/file_io.h"
#include "kerf/geometry/tessellation.h"
#include "kerf/headless/png.h"
#include "kerf/render/gl.h"
#include "ui/picture.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

namespace kerf::window {

namespace {

using geometry::Vec2;
using geometry::Vec3;

void* glfwLoader(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string glfwMessage;
void onGlfwError(int /*code*/, const char* description) { glfwMessage = description ? description : ""; }

constexpr float kTextPanel = 0.30f;
// Above this many triangles the view is drawn from a coarse scene while it moves (orbit, pan, zoom,
// playback): a surface within half a pixel of the exact one at the fitted zoom, no forced pieces,
// and runs of moves that stay within half a pixel of their chord drawn as one patch.
constexpr std::size_t kCoarseAbove = 250'000;  // of the window's width
constexpr float kSidePanel = 290.0f;           // pixels

struct State {
  const WindowRequest* request = nullptr;
  render::Camera camera;
  render::Camera fitted;
  render::RenderOptions options;
  std::optional<std::size_t> selected;
  bool scrollText = false;
  double playback = -1;  // fraction of the moves, < 0 hidden
  bool playing = false;
  // The selection follows the playback wire once the user moves or plays it; a --line given with
  // --playback keeps its block selected until then.
  bool followPlayback = true;
  float step = 0.1f;
  geometry::PathSampleStats stepStats;
  std::vector<std::size_t> firstMoveOfLine;  // per source line (1-based), SIZE_MAX: none
};

/// Points along the cut path at the step, and their worst deviation (the seed's experiment).
geometry::PathSampleStats stepStatistics(const converter::Toolpath& toolpath, double step) {
  std::vector<geometry::Segment> cut;
  for (const auto& m : toolpath.moves)
    if (m.isCut()) cut.push_back(m.lower);
  return geometry::samplePath(cut, geometry::Sampling::step(step), nullptr);
}

/// The move whose lower or upper contour passes nearest the pixel, within 8 pixels.
std::optional<std::size_t> pick(const render::Scene& scene, const render::Camera& camera, Eigen::Vector2d pixel,
                                int width, int height) {
  double best = 8.0;
  std::optional<std::size_t> found;
  for (const render::LineSet* set : {&scene.lower, &scene.upper}) {
    for (std::size_t m = 0; m + 1 < set->moveFirst.size(); ++m) {
      for (std::uint32_t v = set->moveFirst[m]; v + 1 < set->moveFirst[m + 1]; v += 2) {
        const auto& a = set->vertices[v].position;
        const auto& b = set->vertices[v + 1].position;
        const Eigen::Vector2d pa = camera.project(Vec3(a[0], a[1], a[2]), width, height);
        const Eigen::Vector2d pb = camera.project(Vec3(b[0], b[1], b[2]), width, height);
        const Eigen::Vector2d d = pb - pa;
        const double len2 = d.squaredNorm();
        const double t = len2 > 0 ? std::clamp((pixel - pa).dot(d) / len2, 0.0, 1.0) : 0.0;
        const double dist = (pa + t * d - pixel).norm();
        if (dist < best) {
          best = dist;
          found = m;
        }
      }
    }
  }
  return found;
}

std::vector<render::LineVertex> wireAt(const converter::Toolpath& toolpath, const geometry::Planes& planes,
                                       double fraction) {
  if (fraction < 0 || toolpath.moves.empty()) return {};
  const double at = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(toolpath.moves.size());
  const std::size_t m = std::min(toolpath.moves.size() - 1, static_cast<std::size_t>(at));
  const double t = std::clamp(at - static_cast<double>(m), 0.0, 1.0);
  const Vec2 a = toolpath.moves[m].lower.pointAt(t), b = toolpath.upperOf(m).pointAt(t);
  const std::uint32_t red = render::rgba(220, 20, 60);
  return {{{static_cast<float>(a.x()), static_cast<float>(a.y()), static_cast<float>(planes.lower)}, red},
          {{static_cast<float>(b.x()), static_cast<float>(b.y()), static_cast<float>(planes.upper)}, red}};
}

void selectMove(State& s, std::size_t move) {
  s.selected = move;
  s.scrollText = true;
}

// ---- panels ---------------------------------------------------------------------------------

void textPanel(State& s, float width, float height) {
  const converter::SourceFile& src = *s.request->source;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Program", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextUnformatted(src.name().c_str());
  ImGui::Separator();
  ImGui::BeginChild("text");
  const std::uint32_t selectedLine =
      s.selected && *s.selected < s.request->toolpath->moves.size() ? s.request->toolpath->moves[*s.selected].line : 0;
  if (s.scrollText && selectedLine > 0) {
    ImGui::SetScrollY(static_cast<float>(selectedLine - 1) * ImGui::GetTextLineHeightWithSpacing() -
                      0.4f * ImGui::GetWindowHeight());
    s.scrollText = false;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(src.lineCount()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const auto line = static_cast<std::uint32_t>(i + 1);
      const std::string_view text = src.lineText(line);
      char label[32];
      std::snprintf(label, sizeof label, "%5u  ", line);
      std::string row = label;
      row.append(text.substr(0, 200));
      ImGui::PushID(i);
      if (ImGui::Selectable(row.c_str(), line == selectedLine) && line < s.firstMoveOfLine.size() &&
          s.firstMoveOfLine[line] != SIZE_MAX)
        s.selected = s.firstMoveOfLine[line];
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
  ImGui::End();
}

void sidePanel(State& s, float x, float width, float height, bool& screenshot) {
  const WindowRequest& r = *s.request;
  ImGui::SetNextWindowPos(ImVec2(x, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Part", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::Text("%zu moves, %zu triangles", r.scene->moves, r.scene->triangles());
  if (s.selected && *s.selected < r.toolpath->moves.size()) {
    const auto& m = r.toolpath->moves[*s.selected];
    ImGui::Text("selected: move %zu, line %u", *s.selected, m.line);
  } else {
    ImGui::TextUnformatted("click a segment or a line");
  }
  ImGui::Separator();
  ImGui::Checkbox("surface", &s.options.surface);
  ImGui::SameLine();
  ImGui::Checkbox("contours", &s.options.contours);
  ImGui::Checkbox("generators", &s.options.generators);
  ImGui::SameLine();
  ImGui::Checkbox("rapids", &s.options.rapids);
  if (!s.request->reference.empty()) {
    ImGui::SameLine();
    ImGui::Checkbox("drawing", &s.options.reference);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("what the wire path was made from (dashed)");
  }
  ImGui::Checkbox("colour by slope", &s.options.colourBySlope);
  ImGui::Checkbox("highlight findings", &s.options.highlightFindings);
  if (ImGui::Button("fit")) s.camera = s.fitted;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) screenshot = true;

  ImGui::Separator();
  ImGui::TextUnformatted("Wire playback");
  float play = static_cast<float>(std::max(0.0, s.playback));
  if (ImGui::SliderFloat("##play", &play, 0.0f, 1.0f, "%.3f")) {
    s.playback = play;
    s.followPlayback = true;
  }
  ImGui::SameLine();
  if (ImGui::Button(s.playing ? "stop" : "play")) {
    s.playing = !s.playing;
    s.followPlayback = true;
    if (s.playback < 0) s.playback = 0;
  }

  ImGui::Separator();
  ImGui::TextUnformatted("Interpolation step k (mm)");
  if (ImGui::SliderFloat("##step", &s.step, 0.001f, 5.0f, "%.3f", ImGuiSliderFlags_Logarithmic))
    s.stepStats = stepStatistics(*r.toolpath, s.step);
  ImGui::Text("%zu points, max error %.6f mm", s.stepStats.points, s.stepStats.maxDeviation);

  ImGui::Separator();
  ImGui::Text("Findings (%zu)", r.findings.size());
  ImGui::BeginChild("findings");
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    const converter::Diagnostic& d = r.findings[i];
    const std::string text = converter::codeName(d.code) + " " + converter::severityName(d.severity) + ": " + d.message;
    ImGui::PushID(static_cast<int>(i));
    // The whole message, wrapped to the panel: a selectable row as tall as the wrapped text, the
    // text drawn over it.
    const float wrap = ImGui::GetContentRegionAvail().x;
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const bool clicked = ImGui::Selectable("##finding", d.move && s.selected == d.move, 0, ImVec2(0, size.y));
    ImGui::GetWindowDrawList()->AddText(nullptr, 0.0f, at, ImGui::GetColorU32(ImGuiCol_Text), text.c_str(), nullptr,
                                        wrap);
    if (clicked) {
      if (d.move) selectMove(s, *d.move);
      if (d.point) {
        s.camera.target = *d.point;
        s.camera.halfHeight = std::max(0.25 * s.fitted.halfHeight, 1e-3);
      }
    }
    ImGui::PopID();
  }
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace

bool runWindow(const WindowRequest& request, std::string& error) {
  glfwSetErrorCallback(&onGlfwError);
  if (!glfwInit()) {
    error = "kerf view needs a display (" + glfwMessage +
            "): run it on a desktop or under xvfb-run; for a picture without a display use kerf render";
    return false;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const std::string title = "kerf view - " + request.source->name();
  GLFWwindow* window = glfwCreateWindow(request.width, request.height, title.c_str(), nullptr, nullptr);
  if (!window) {
    error = "cannot open an OpenGL 3.3 core window: " + glfwMessage;
    glfwTerminate();
    return false;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(request.benchmark || request.frames > 0 ? 0 : 1);
  bool ok = render::loadGl(&glfwLoader, error);

  State s;
  s.request = &request;
  s.options = request.options;
  // Drawn in one call: waiting for the rasteriser between pieces slows every frame of a large part
  // noticeably, and glFlush instead of glFinish bounds nothing. So a window on a part whose walls
  // pile up on screen (a star of 1e6 spikes) takes llvmpipe's memory for the bins; a headless
  // picture does not (RenderOptions::drawChunk).
  s.options.drawChunk = std::numeric_limits<std::size_t>::max();
  s.playback = request.playback;
  s.step = static_cast<float>(request.step);
  s.stepStats = stepStatistics(*request.toolpath, request.step);
  s.firstMoveOfLine.assign(request.source->lineCount() + 2, SIZE_MAX);
  for (std::size_t i = 0; i < request.toolpath->moves.size(); ++i) {
    const std::uint32_t line = request.toolpath->moves[i].line;
    if (line < s.firstMoveOfLine.size() && s.firstMoveOfLine[line] == SIZE_MAX) s.firstMoveOfLine[line] = i;
  }
  if (request.selectLine && *request.selectLine < s.firstMoveOfLine.size() &&
      s.firstMoveOfLine[*request.selectLine] != SIZE_MAX) {
    selectMove(s, s.firstMoveOfLine[*request.selectLine]);
    s.followPlayback = false;
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.BackendRendererName = "kerf::render";
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  ImGui::StyleColorsLight();
  ImGui_ImplGlfw_InitForOpenGL(window, true);

  {
    render::Renderer renderer;
    render::Renderer coarseRenderer;
    std::optional<render::Scene> coarse;
    render::OffscreenTarget target;
    unsigned char* fontPixels = nullptr;
    int fontW = 0, fontH = 0;
    if (ok) ok = renderer.init(error);
    if (ok) {
      unsigned char* pixels = nullptr;
      int fw = 0, fh = 0;
      io.Fonts->GetTexDataAsRGBA32(&pixels, &fw, &fh);
      io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(1)));
      renderer.setOverlayTexture(fw, fh, pixels);
      renderer.setScene(*request.scene);
      fontPixels = pixels;
      fontW = fw;
      fontH = fh;
    }
    int targetW = 0, targetH = 0;
    bool fittedOnce = false;
    std::vector<double> frameSeconds;
    int frame = 0;
    double lastPlaybackDrawn = -2;
    // What the offscreen target holds: while the view, its options, the playback wire and the
    // level stay the same, a frame shows it again (a resolve) instead of drawing the scene, so
    // the panels answer at once at rest even with 1e6 triangles. --benchmark always draws.
    struct Drawn {
      render::Camera camera;
      std::array<bool, 9> switches{};  // RenderOptions' switches, in sameSwitches' order
      float lineWidth = 0.0f;
      std::uint32_t background = 0;
      std::size_t selected = SIZE_MAX;
      double playback = -2;
      bool coarse = false;
      bool valid = false;
    } shown;
    // (drawChunk is not among them: it changes how the picture is drawn, not the picture.)
    static_assert(sizeof(render::RenderOptions) == 48, "a new RenderOptions field must join Drawn and switchesOf");
    auto switchesOf = [](const render::RenderOptions& o) {
      return std::array<bool, 9>{o.surface, o.contours, o.generators,    o.rapids,           o.reference,
                                 o.markers, o.triad,    o.colourBySlope, o.highlightFindings};
    };
    bool dragging = false;
    Eigen::Vector2d pressAt{0, 0};
    while (ok && !glfwWindowShouldClose(window)) {
      const auto t0 = std::chrono::steady_clock::now();
      glfwPollEvents();
      int fbW = 0, fbH = 0;
      glfwGetFramebufferSize(window, &fbW, &fbH);
      if (fbW <= 0 || fbH <= 0) continue;
      const float textW = std::floor(kTextPanel * static_cast<float>(fbW));
      const float sideW = std::min(kSidePanel, 0.3f * static_cast<float>(fbW));
      const int viewX = static_cast<int>(textW);
      const int viewW = std::max(16, fbW - static_cast<int>(textW) - static_cast<int>(sideW));
      const int viewH = fbH;
      if (viewW != targetW || viewH != targetH) {
        // Fitted below the title, and clear of the triad in the bottom-left corner.
        s.fitted = render::clearOfTriad(render::fitCamera(request.scene->boundsMin, request.scene->boundsMax,
                                                          render::View::Iso, viewW, viewH, 0.08, 36),
                                        request.scene->boundsMin, request.scene->boundsMax, viewW, viewH);
        if (!target.create(viewW, viewH, ui::autoSamples(*request.scene, viewW, viewH, s.fitted.mmPerPixel(viewH)),
                           error)) {
          ok = false;
          break;
        }
        targetW = viewW;
        targetH = viewH;
        shown.valid = false;
        if (!fittedOnce) s.camera = s.fitted;
        fittedOnce = true;
        if (!coarse && request.scene->triangles() > kCoarseAbove) {
          render::SceneOptions so = request.sceneOptions;
          so.tolerance = std::max(so.tolerance, 0.5 * s.fitted.mmPerPixel(viewH));
          so.mergeTolerance = 0.5 * s.fitted.mmPerPixel(viewH);
          so.minTaperPieces = 1;
          coarse = render::buildScene(*request.toolpath, request.findings, so, request.reference);
          if (!coarseRenderer.init(error)) {
            ok = false;
            break;
          }
          coarseRenderer.setScene(*coarse);
          coarseRenderer.setOverlayTexture(fontW, fontH, fontPixels);
          std::fprintf(stderr, "kerf view: %zu triangles; %zu drawn while the view moves\n", request.scene->triangles(),
                       coarse->triangles());
        }
      }

      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      bool screenshot = false;
      textPanel(s, textW, static_cast<float>(fbH));
      sidePanel(s, static_cast<float>(fbW) - sideW, sideW, static_cast<float>(fbH), screenshot);

      // Mouse in the 3D view: drag left to orbit, right or middle to pan, wheel to zoom, click to pick.
      const ImVec2 mouse = io.MousePos;
      const Eigen::Vector2d local(mouse.x - static_cast<float>(viewX), mouse.y);
      const bool inView =
          !io.WantCaptureMouse && local.x() >= 0 && local.x() < viewW && local.y() >= 0 && local.y() < viewH;
      if (inView && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        pressAt = local;
        dragging = true;
      }
      if (dragging && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
        const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
        s.camera.yaw -= 0.01 * dx;
        s.camera.pitch = std::clamp(s.camera.pitch + 0.01 * dy, -0.5 * geometry::kPi, 0.5 * geometry::kPi);
      }
      if (dragging && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
        dragging = false;
        if ((local - pressAt).norm() < 3.0)
          if (auto m = pick(*request.scene, s.camera, local, viewW, viewH)) selectMove(s, *m);
      }
      if (inView && (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 1.0f) ||
                     ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 1.0f))) {
        const double mm = s.camera.mmPerPixel(viewH);
        const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
        s.camera.target += -mm * dx * s.camera.right() + mm * dy * s.camera.up();
      }
      const bool moving = request.coarseFrames || s.playing ||
                          (dragging && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) ||
                          (inView && (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 1.0f) ||
                                      ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 1.0f) || io.MouseWheel != 0.0f));
      if (inView && io.MouseWheel != 0.0f) s.camera.halfHeight *= std::pow(0.85, static_cast<double>(io.MouseWheel));

      if (s.playing) {
        s.playback += 0.002;
        if (s.playback > 1.0) s.playback = 0.0;
      }
      if (s.playback != lastPlaybackDrawn) {
        renderer.setExtraLines(wireAt(*request.toolpath, request.scene->planes, s.playback), 3.0f);
        if (coarse) coarseRenderer.setExtraLines(wireAt(*request.toolpath, request.scene->planes, s.playback), 3.0f);
        lastPlaybackDrawn = s.playback;
        if (s.playback >= 0 && s.followPlayback && !request.toolpath->moves.empty()) {
          const auto m =
              std::min(request.toolpath->moves.size() - 1,
                       static_cast<std::size_t>(s.playback * static_cast<double>(request.toolpath->moves.size())));
          if (!s.selected || *s.selected != m) {
            s.selected = m;
            s.scrollText = s.playing;
          }
        }
      }

      // The annotations of the picture, in the view's area.
      // Drawn in the view's own coordinates (ImGui culls text against the clip rectangle as it
      // draws), then moved right by the text panel's width, clip rectangles included.
      ImDrawList* fg = ImGui::GetForegroundDrawList();
      fg->PushClipRect(ImVec2(0, 0), ImVec2(static_cast<float>(viewW), static_cast<float>(viewH)));
      const int vtxStart = fg->VtxBuffer.Size;
      const int cmdStart = fg->CmdBuffer.Size - 1;
      render::RenderOptions options = s.options;
      options.selectedMove = s.selected;
      ui::drawAnnotations(*fg, *request.scene, s.camera, options, request.annotation, viewW, viewH);
      for (int v = vtxStart; v < fg->VtxBuffer.Size; ++v) fg->VtxBuffer[v].pos.x += static_cast<float>(viewX);
      for (int c = std::max(0, cmdStart); c < fg->CmdBuffer.Size; ++c) {
        fg->CmdBuffer[c].ClipRect.x += static_cast<float>(viewX);
        fg->CmdBuffer[c].ClipRect.z += static_cast<float>(viewX);
      }
      fg->PopClipRect();
      ImGui::Render();

      target.bind();
      render::Renderer& drawing = moving && coarse ? coarseRenderer : renderer;
      const bool coarseNow = &drawing == &coarseRenderer;
      const std::size_t selectedNow = options.selectedMove ? *options.selectedMove : SIZE_MAX;
      if (request.benchmark || !shown.valid || !(shown.camera == s.camera) || shown.switches != switchesOf(options) ||
          shown.lineWidth != options.lineWidth || shown.background != options.background ||
          shown.selected != selectedNow || shown.playback != lastPlaybackDrawn || shown.coarse != coarseNow) {
        drawing.render(s.camera, options, viewW, viewH);
        shown.camera = s.camera;
        shown.switches = switchesOf(options);
        shown.lineWidth = options.lineWidth;
        shown.background = options.background;
        shown.selected = selectedNow;
        shown.playback = lastPlaybackDrawn;
        shown.coarse = coarseNow;
        shown.valid = true;
      }
      const render::GlApi& g = render::gl();
      g.BindFramebuffer(GL_FRAMEBUFFER, 0);
      g.Viewport(0, 0, fbW, fbH);
      g.ClearColor(0.94f, 0.94f, 0.94f, 1.0f);
      g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      target.resolveTo(0, viewX, 0);
      drawing.drawOverlay(ui::convertDrawData(*ImGui::GetDrawData()), fbW, fbH);
      ++frame;
      const bool last = request.frames > 0 && frame >= request.frames;
      if (screenshot || (last && request.screenshot)) {
        g.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        g.ReadBuffer(GL_BACK);
        const std::string png = headless::encodePng(render::readFramebufferRgba(fbW, fbH), fbW, fbH);
        const std::string path = last && request.screenshot ? *request.screenshot : "kerf-screenshot.png";
        std::string writeError;
        if (png.empty() || !cli::writeOutput(path, request.inputs, png, writeError)) {
          error = "cannot write the screenshot '" + path + "': " + (png.empty() ? "PNG encoding failed" : writeError);
          ok = false;
        } else {
          std::cerr << "kerf: wrote the window (" << fbW << "x" << fbH << ") to " << path << "\n";
        }
      }
      if (request.benchmark) g.Finish();
      glfwSwapBuffers(window);
      frameSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (last) break;
    }
    if (request.benchmark && frameSeconds.size() > 1) {
      std::vector<double> sorted(frameSeconds.begin() + 1, frameSeconds.end());  // the first frame uploads
      std::sort(sorted.begin(), sorted.end());
      double sum = 0;
      for (double v : sorted) sum += v;
      const double mean = sum / static_cast<double>(sorted.size());
      const double median = sorted[sorted.size() / 2], worst = sorted[sorted.size() - 1];
      const bool coarseShown = coarse.has_value() && request.coarseFrames;
      const std::size_t drawn = coarseShown ? coarse.value().triangles() : request.scene->triangles();
      std::fprintf(
          stderr,
          "kerf view: %zu frames, %zu triangles%s, frame time mean %.1f ms, median %.1f ms, max %.1f ms (%.1f fps)\n",
          sorted.size(), drawn, coarseShown ? " (coarse level)" : "", mean * 1e3, median * 1e3, worst * 1e3,
          1.0 / mean);
    }
  }
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return ok;
}

}  // namespace kerf::window
