// The interactive window (window.h): GLFW and Dear ImGui, the program text beside the part.
// Sections: 1. GL loading through GLFW and the window's state  2. picking  3. panels  4. opening the window
//           5. the frame loop
#include "window/window.h"

#include "cli/file_io.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/tessellation.h"
#include "kerf/headless/png.h"
#include "kerf/render/construction_scene.h"
#include "kerf/render/gl.h"
#include "ui/picture.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <utility>

namespace kerf::window {

namespace {

using geometry::Vec2;
using geometry::Vec3;

// ---- 1. GL loading through GLFW and the window's state ------------------------------------------

void* glfwLoader(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string glfwMessage;
void onGlfwError(int /*code*/, const char* description) { glfwMessage = description ? description : ""; }

// Block steps asked for with the keyboard since the last frame (+ next, - back). Counted from GLFW's
// own key events: a press and its release within one poll never show in ImGui 1.86's key state.
int pendingSteps = 0;
void onKey(GLFWwindow* /*window*/, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action == GLFW_RELEASE) return;
  if (key == GLFW_KEY_DOWN || key == GLFW_KEY_PAGE_DOWN) ++pendingSteps;
  if (key == GLFW_KEY_UP || key == GLFW_KEY_PAGE_UP) --pendingSteps;
}

constexpr float kTextPanel = 0.30f;
constexpr float kSidePanel = 290.0f;  // pixels

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
  std::vector<std::size_t> firstMoveOfLine;        // per source line (1-based), SIZE_MAX: none
  std::vector<bool> passShown;                     // per pass, contour after contour (the pass list)
  bool passesChanged = false;                      // a pass was shown or hidden: the scene is built again
  bool construction = true;                        // the selected block's construction drawn (teaching)
  bool frameConstruction = false;                  // stepped with the keyboard: the view frames the next one
  const converter::Construction* block = nullptr;  // the selected block's, for the block panel
};

// ---- 2. picking ---------------------------------------------------------------------------------

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

// ---- 3. panels ----------------------------------------------------------------------------------

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

/// The contours and passes of a program cut in several passes: a box shows or hides each pass, a
/// click on it selects its first move and puts the playback wire there.
void passList(State& s) {
  const converter::Structure* st = s.request->structure;
  if (s.passShown.empty() || !st) return;
  ImGui::Separator();
  ImGui::TextUnformatted("Passes (the box shows or hides one)");
  const double moves = static_cast<double>(std::max<std::size_t>(s.request->toolpath->moves.size(), 1));
  std::size_t at = 0;
  for (std::size_t ci = 0; ci < st->contours.size(); ++ci) {
    ImGui::Text("contour %zu from %s", ci + 1, converter::formatPoint(st->contours[ci].startHole).c_str());
    for (std::size_t k = 0; k < st->contours[ci].passes.size(); ++k, ++at) {
      const converter::Pass& p = st->contours[ci].passes[k];
      ImGui::PushID(static_cast<int>(at));
      bool shown = s.passShown[at];
      if (ImGui::Checkbox("##shown", &shown)) {
        s.passShown[at] = shown;
        s.passesChanged = true;
      }
      ImGui::SameLine();
      const std::uint32_t c = render::passColour(k + 1);
      ImGui::ColorButton("##colour", ImGui::ColorConvertU32ToFloat4(c), ImGuiColorEditFlags_NoTooltip,
                         ImVec2(ImGui::GetFrameHeight() * 0.6f, ImGui::GetFrameHeight()));
      ImGui::SameLine();
      // Short enough for the panel: the register and value, the lines; the rest in the tooltip.
      const std::string label = "pass " + std::to_string(k + 1) + ": " +
                                (p.offsetRegister.empty() ? std::string() : p.offsetRegister + " ") +
                                (p.offset ? converter::formatFixed(*p.offset, 3) + ", " : std::string()) +
                                std::to_string(p.firstLine) + "-" + std::to_string(p.lastLine);
      if (ImGui::Selectable(label.c_str(), s.selected && *s.selected >= p.first && *s.selected < p.end)) {
        selectMove(s, p.first);
        s.playback = static_cast<double>(p.first) / moves;
        s.followPlayback = false;
      }
      if (ImGui::IsItemHovered()) {
        const std::string more = converter::offsetText(p) + ", " + converter::directionName(p.direction) + ", " +
                                 (p.closes   ? "closes"
                                  : p.cutOff ? "cuts off the tab"
                                             : "leaves a tab") +
                                 ", " + converter::formatFixed(p.length, 3) + " mm" +
                                 (p.minutes ? ", " + converter::formatFixed(*p.minutes, 1) + " min" : std::string());
        ImGui::SetTooltip("%s", more.c_str());
      }
      ImGui::PopID();
    }
  }
}

/// --drawing: the drawing's elements cut out of tolerance, worst first, each selecting the block
/// nearest it and framing the point; a taper's upper plane (--drawing-upper) in a list of its own.
void deviationList(State& s, const converter::DrawingComparison* c, const char* plane, double z) {
  if (c == nullptr) return;
  std::vector<const converter::ElementDeviation*> off;
  for (const converter::ElementDeviation& e : c->elements)
    if (e.deviation > c->tolerance) off.push_back(&e);
  std::stable_sort(off.begin(), off.end(), [](auto* a, auto* b) { return a->deviation > b->deviation; });
  ImGui::Separator();
  ImGui::Text("%s: %zu of %zu elements off by more than %.1f um", plane, off.size(), c->elements.size(),
              c->tolerance * 1000.0);
  ImGui::PushID(plane);
  for (std::size_t i = 0; i < off.size(); ++i) {
    const converter::ElementDeviation& e = *off[i];
    const std::string row = converter::formatFixed(e.deviation * 1000.0, 1) + " um: DXF line " +
                            std::to_string(e.drawingLine) + ", block line " + std::to_string(e.blockLine);
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Selectable(row.c_str(), s.selected == e.move)) {
      selectMove(s, e.move);
      s.camera.target = {e.at.x(), e.at.y(), z};
      s.camera.halfHeight = std::max(0.25 * s.fitted.halfHeight, 1e-3);
    }
    ImGui::PopID();
  }
  ImGui::PopID();
}

/// The selected block: each word and what it sets, the modes it inherits, its pass, and what the
/// construction in the view marks (docs/teaching.md).
void blockPanel(State& s) {
  if (!s.block) return;
  const converter::Construction& b = *s.block;
  ImGui::Separator();
  ImGui::Checkbox("construction", &s.construction);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("draw how the block's geometry follows from its words");
  ImGui::SameLine();
  ImGui::TextDisabled("(Up/Down: step)");
  if (!ImGui::CollapsingHeader("Block", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::TextWrapped("line %u: %s", b.line, b.block.c_str());
  if (!b.pass.empty()) ImGui::TextWrapped("%s", b.pass.c_str());
  for (const converter::WordMeaning& w : b.words) {
    ImGui::TextColored(ImVec4(0.1f, 0.35f, 0.75f, 1.0f), "%s", w.word.c_str());
    ImGui::SameLine();
    ImGui::TextWrapped("%s", w.sets.c_str());
  }
  ImGui::TextDisabled("inherits");
  for (const std::string& m : b.modes) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s", m.c_str());
  }
  if (s.construction) {
    ImGui::TextDisabled("drawn");
    for (const converter::ConstructionMark& m : b.marks)
      if (!m.label.empty()) {
        const std::uint32_t c = render::constructionColour(m.role);
        ImGui::PushStyleColor(
            ImGuiCol_Text, ImVec4(static_cast<float>(c & 0xFF) / 255.0f, static_cast<float>((c >> 8) & 0xFF) / 255.0f,
                                  static_cast<float>((c >> 16) & 0xFF) / 255.0f, 1.0f));
        ImGui::TextWrapped("%s", m.label.c_str());
        ImGui::PopStyleColor();
      }
  }
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
  if (ImGui::Checkbox("colour by slope", &s.options.colourBySlope) && s.options.colourBySlope)
    s.options.colourByPass = false;
  if (!s.passShown.empty()) {
    ImGui::SameLine();
    if (ImGui::Checkbox("by pass", &s.options.colourByPass) && s.options.colourByPass) s.options.colourBySlope = false;
  }
  ImGui::Checkbox("highlight findings", &s.options.highlightFindings);
  if (ImGui::Button("fit")) s.camera = s.fitted;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) screenshot = true;

  blockPanel(s);
  passList(s);
  deviationList(s, s.request->comparison, s.request->comparisonUpper ? "Drawing, lower plane" : "Drawing",
                s.request->scene->planes.lower);
  deviationList(s, s.request->comparisonUpper, "Drawing, upper plane", s.request->scene->planes.upper);
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

// ---- 4. opening the window ----------------------------------------------------------------------

/// Opens the window with an OpenGL 3.3 core context, made current; null with the reason in error.
GLFWwindow* openWindow(const WindowRequest& request, std::string& error) {
  glfwSetErrorCallback(&onGlfwError);
  if (!glfwInit()) {
    error = "kerf view needs a display (" + glfwMessage +
            "): run it on a desktop or under xvfb-run; for a picture without a display use kerf render";
    return nullptr;
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
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(request.benchmark || request.frames > 0 ? 0 : 1);
  return window;
}

/// The state a window starts with: the request's options, playback, step and selected line.
void startState(State& s, const WindowRequest& request) {
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
  if (request.structure && request.structure->multiPass())
    for (const converter::Contour& c : request.structure->contours)
      s.passShown.resize(s.passShown.size() + c.passes.size(), true);
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
}

/// What the offscreen target holds: while the view, its options, the playback wire and the level
/// stay the same, a frame shows it again (a resolve) instead of drawing the scene, so the panels
/// answer at once at rest even with 1e6 triangles. --benchmark always draws. (drawChunk is not
/// among them: it changes how the picture is drawn, not the picture.)
struct Drawn {
  render::Camera camera;
  std::array<bool, 10> switches{};  // RenderOptions' switches, in switchesOf's order
  float lineWidth = 0.0f;
  std::uint32_t background = 0;
  std::size_t selected = SIZE_MAX;
  double playback = -2;
  bool coarse = false;
  bool valid = false;
};
static_assert(sizeof(render::RenderOptions) == 48, "a new RenderOptions field must join Drawn and switchesOf");
std::array<bool, 10> switchesOf(const render::RenderOptions& o) {
  return {o.surface, o.contours, o.generators,    o.rapids,       o.reference,
          o.markers, o.triad,    o.colourBySlope, o.colourByPass, o.highlightFindings};
}

/// Where the three parts of a frame lie, in framebuffer pixels: text panel, 3D view, side panel.
struct Layout {
  int fbW = 0, fbH = 0;
  float textW = 0, sideW = 0;
  int viewX = 0, viewW = 0, viewH = 0;
};

// ---- 5. the frame loop --------------------------------------------------------------------------

/// The frame loop's resources and what one frame keeps for the next.
class FrameLoop {
 public:
  FrameLoop(const WindowRequest& request, GLFWwindow* window, State& s) : request_(request), window_(window), s_(s) {}

  /// The renderer, with the font as its overlay texture and the scene uploaded.
  bool init(std::string& error);
  /// One frame; false when the loop must stop (an error in `error`, or the last frame asked for).
  bool frame(std::string& error, bool& failed);
  /// --benchmark: the frame times (the first frame, which uploads, left out).
  void reportFrameTimes() const;

 private:
  Layout layout() const;
  /// On a new view size: the camera fitted to it, the offscreen target, and the coarse level.
  bool fitView(const Layout& l, std::string& error);
  /// Orbit, pan, zoom and pick; true while the view moves.
  bool handleMouse(const Layout& l);
  void advancePlayback();
  /// After a pass was shown or hidden: the scene (and the coarse one) built again without the
  /// hidden passes' moves.
  void showPasses();
  /// The scene drawn now: the request's, or the one without the hidden passes.
  [[nodiscard]] const render::Scene& scene() const { return shownScene_ ? *shownScene_ : *request_.scene; }
  /// Up and Down (Page Up, Page Down) step the selection block by block (onKey counts them).
  void stepWithKeys();
  /// The selected block's construction at the step, built when the block or the step changes and
  /// given to both renderers; framed when the keyboard stepped to it.
  void construct();
  void annotate(const render::RenderOptions& options, const Layout& l);
  render::Renderer& drawView(const render::RenderOptions& options, bool moving, const Layout& l);
  bool saveScreenshot(const Layout& l, bool last, std::string& error);

  const WindowRequest& request_;
  GLFWwindow* window_;
  State& s_;
  render::Renderer renderer_, coarseRenderer_;
  std::optional<render::Scene> coarse_;
  std::optional<render::Scene> shownScene_;
  render::OffscreenTarget target_;
  unsigned char* fontPixels_ = nullptr;
  int fontW_ = 0, fontH_ = 0;
  int targetW_ = 0, targetH_ = 0;
  bool fittedOnce_ = false;
  std::vector<double> frameSeconds_;
  int frame_ = 0;
  double lastPlaybackDrawn_ = -2;
  Drawn shown_;
  bool dragging_ = false;
  Eigen::Vector2d pressAt_{0, 0};
  converter::Construction block_;
  render::ConstructionScene construction_;
  std::optional<std::size_t> constructedMove_;
  float constructedStep_ = -1.0f;
  bool constructionShown_ = false;
};

bool FrameLoop::init(std::string& error) {
  if (!renderer_.init(error)) return false;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->GetTexDataAsRGBA32(&fontPixels_, &fontW_, &fontH_);
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(1)));
  renderer_.setOverlayTexture(fontW_, fontH_, fontPixels_);
  renderer_.setScene(*request_.scene);
  return true;
}

Layout FrameLoop::layout() const {
  Layout l;
  glfwGetFramebufferSize(window_, &l.fbW, &l.fbH);
  l.textW = std::floor(kTextPanel * static_cast<float>(l.fbW));
  l.sideW = std::min(kSidePanel, 0.3f * static_cast<float>(l.fbW));
  l.viewX = static_cast<int>(l.textW);
  l.viewW = std::max(16, l.fbW - static_cast<int>(l.textW) - static_cast<int>(l.sideW));
  l.viewH = l.fbH;
  return l;
}

bool FrameLoop::fitView(const Layout& l, std::string& error) {
  const render::Scene& scene = *request_.scene;
  // Fitted below the title, and clear of the triad in the bottom-left corner.
  s_.fitted = render::clearOfTriad(
      render::fitCamera(scene.boundsMin, scene.boundsMax, render::View::Iso, l.viewW, l.viewH, 0.08, 36),
      scene.boundsMin, scene.boundsMax, l.viewW, l.viewH);
  if (!target_.create(l.viewW, l.viewH, ui::autoSamples(scene, l.viewW, l.viewH, s_.fitted.mmPerPixel(l.viewH)), error))
    return false;
  targetW_ = l.viewW;
  targetH_ = l.viewH;
  shown_.valid = false;
  if (!fittedOnce_) s_.camera = s_.fitted;
  fittedOnce_ = true;
  // Above render::kCoarseAboveTriangles the view is drawn from a coarse scene while it moves
  // (orbit, pan, zoom, playback), at the fitted zoom's pixel.
  if (coarse_ || scene.triangles() <= render::kCoarseAboveTriangles) return true;
  const render::SceneOptions so = render::coarseSceneOptions(request_.sceneOptions, s_.fitted.mmPerPixel(l.viewH));
  coarse_ = render::buildScene(*request_.toolpath, request_.findings, so, request_.reference);
  if (!coarseRenderer_.init(error)) return false;
  coarseRenderer_.setScene(*coarse_);
  coarseRenderer_.setOverlayTexture(fontW_, fontH_, fontPixels_);
  std::fprintf(stderr, "kerf view: %zu triangles; %zu drawn while the view moves\n", scene.triangles(),
               coarse_->triangles());
  return true;
}

bool FrameLoop::handleMouse(const Layout& l) {
  // Drag left to orbit, right or middle to pan, wheel to zoom, click to pick.
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 mouse = io.MousePos;
  const Eigen::Vector2d local(mouse.x - static_cast<float>(l.viewX), mouse.y);
  const bool inView =
      !io.WantCaptureMouse && local.x() >= 0 && local.x() < l.viewW && local.y() >= 0 && local.y() < l.viewH;
  if (inView && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    pressAt_ = local;
    dragging_ = true;
  }
  if (dragging_ && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    s_.camera.yaw -= 0.01 * dx;
    s_.camera.pitch = std::clamp(s_.camera.pitch + 0.01 * dy, -0.5 * geometry::kPi, 0.5 * geometry::kPi);
  }
  if (dragging_ && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    dragging_ = false;
    if ((local - pressAt_).norm() < 3.0)
      if (auto m = pick(scene(), s_.camera, local, l.viewW, l.viewH)) selectMove(s_, *m);
  }
  const bool panning =
      ImGui::IsMouseDragging(ImGuiMouseButton_Right, 1.0f) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 1.0f);
  if (inView && panning) {
    const double mm = s_.camera.mmPerPixel(l.viewH);
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    s_.camera.target += -mm * dx * s_.camera.right() + mm * dy * s_.camera.up();
  }
  const bool moving = request_.coarseFrames || s_.playing ||
                      (dragging_ && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) ||
                      (inView && (panning || io.MouseWheel != 0.0f));
  if (inView && io.MouseWheel != 0.0f) s_.camera.halfHeight *= std::pow(0.85, static_cast<double>(io.MouseWheel));
  return moving;
}

void FrameLoop::advancePlayback() {
  if (s_.playing) {
    s_.playback += 0.002;
    if (s_.playback > 1.0) s_.playback = 0.0;
  }
  if (s_.playback == lastPlaybackDrawn_) return;
  const converter::Toolpath& toolpath = *request_.toolpath;
  renderer_.setExtraLines(wireAt(toolpath, request_.scene->planes, s_.playback), 3.0f);
  if (coarse_) coarseRenderer_.setExtraLines(wireAt(toolpath, request_.scene->planes, s_.playback), 3.0f);
  lastPlaybackDrawn_ = s_.playback;
  if (s_.playback >= 0 && s_.followPlayback && !toolpath.moves.empty()) {
    const auto m = std::min(toolpath.moves.size() - 1,
                            static_cast<std::size_t>(s_.playback * static_cast<double>(toolpath.moves.size())));
    if (!s_.selected || *s_.selected != m) {
      s_.selected = m;
      s_.scrollText = s_.playing;
    }
  }
}

void FrameLoop::showPasses() {
  if (!s_.passesChanged) return;
  s_.passesChanged = false;
  const converter::Structure& st = *request_.structure;
  render::SceneOptions so = request_.sceneOptions;
  so.hiddenMoves.assign(request_.toolpath->moves.size(), false);
  std::size_t at = 0;
  for (const converter::Contour& c : st.contours)
    for (const converter::Pass& p : c.passes)
      if (!s_.passShown[at++])
        for (std::size_t m = p.first; m < p.end && m < so.hiddenMoves.size(); ++m) so.hiddenMoves[m] = true;
  shownScene_ = render::buildScene(*request_.toolpath, request_.findings, so, request_.reference);
  renderer_.setScene(*shownScene_);
  if (coarse_) {
    coarse_ = render::buildScene(*request_.toolpath, request_.findings,
                                 render::coarseSceneOptions(so, s_.fitted.mmPerPixel(targetH_)), request_.reference);
    coarseRenderer_.setScene(*coarse_);
  }
  shown_.valid = false;
}

void FrameLoop::stepWithKeys() {
  const std::size_t moves = request_.toolpath->moves.size();
  const int steps = std::exchange(pendingSteps, 0);
  if (ImGui::GetIO().WantTextInput || moves == 0 || steps == 0) return;
  const auto n = static_cast<long long>(moves);
  long long m = s_.selected ? static_cast<long long>(*s_.selected) : (steps > 0 ? -1 : n);
  m = ((m + steps) % n + n) % n;
  selectMove(s_, static_cast<std::size_t>(m));
  s_.followPlayback = false;
  s_.frameConstruction = true;
}

void FrameLoop::construct() {
  const bool show = s_.construction && s_.selected && *s_.selected < request_.toolpath->moves.size();
  if (show && (constructedMove_ != s_.selected || constructedStep_ != s_.step)) {
    block_ = converter::constructionOf(*request_.source, *request_.toolpath, request_.structure,
                                       geometry::Sampling::step(s_.step), *s_.selected, request_.parse);
    construction_ = render::constructionScene(block_, scene().planes, 0.25 * s_.camera.mmPerPixel(targetH_), 0);
    constructedMove_ = s_.selected;
    constructedStep_ = s_.step;
    constructionShown_ = false;
  }
  s_.block = constructedMove_ && s_.selected == constructedMove_ ? &block_ : nullptr;
  if (show != constructionShown_ || (show && !shown_.valid)) {
    const render::ConstructionScene none;
    renderer_.setConstruction(show ? construction_ : none);
    coarseRenderer_.setConstruction(show ? construction_ : none);
    constructionShown_ = show;
    shown_.valid = false;
  }
  if (show && s_.frameConstruction) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    render::extendBounds(construction_, lo, hi);
    if (lo.allFinite() && hi.allFinite()) {
      // Half the box's larger side, with room for a turned view (a diagonal is up to 1.4 times a
      // side) and for a view narrower than it is tall.
      const double aspect = targetH_ > 0 ? static_cast<double>(targetW_) / targetH_ : 1.0;
      s_.camera.target = 0.5 * (lo + hi);
      s_.camera.halfHeight = std::max(0.75 * (hi - lo).head<2>().maxCoeff() / std::min(aspect, 1.0), 1e-3);
    }
  }
  s_.frameConstruction = false;
}

void FrameLoop::annotate(const render::RenderOptions& options, const Layout& l) {
  // Drawn in the view's own coordinates (ImGui culls text against the clip rectangle as it draws),
  // then moved right by the text panel's width, clip rectangles included.
  ImDrawList* fg = ImGui::GetForegroundDrawList();
  fg->PushClipRect(ImVec2(0, 0), ImVec2(static_cast<float>(l.viewW), static_cast<float>(l.viewH)));
  const int vtxStart = fg->VtxBuffer.Size;
  const int cmdStart = fg->CmdBuffer.Size - 1;
  ui::Annotation annotation = request_.annotation;
  if (constructionShown_) annotation.construction = &construction_;
  ui::drawAnnotations(*fg, scene(), s_.camera, options, annotation, l.viewW, l.viewH);
  for (int v = vtxStart; v < fg->VtxBuffer.Size; ++v) fg->VtxBuffer[v].pos.x += static_cast<float>(l.viewX);
  for (int c = std::max(0, cmdStart); c < fg->CmdBuffer.Size; ++c) {
    fg->CmdBuffer[c].ClipRect.x += static_cast<float>(l.viewX);
    fg->CmdBuffer[c].ClipRect.z += static_cast<float>(l.viewX);
  }
  fg->PopClipRect();
}

render::Renderer& FrameLoop::drawView(const render::RenderOptions& options, bool moving, const Layout& l) {
  target_.bind();
  render::Renderer& drawing = moving && coarse_ ? coarseRenderer_ : renderer_;
  const bool coarseNow = &drawing == &coarseRenderer_;
  const std::size_t selectedNow = options.selectedMove ? *options.selectedMove : SIZE_MAX;
  if (request_.benchmark || !shown_.valid || !(shown_.camera == s_.camera) || shown_.switches != switchesOf(options) ||
      shown_.lineWidth != options.lineWidth || shown_.background != options.background ||
      shown_.selected != selectedNow || shown_.playback != lastPlaybackDrawn_ || shown_.coarse != coarseNow) {
    drawing.render(s_.camera, options, l.viewW, l.viewH);
    shown_ = {s_.camera,   switchesOf(options), options.lineWidth, options.background,
              selectedNow, lastPlaybackDrawn_,  coarseNow,         true};
  }
  return drawing;
}

bool FrameLoop::saveScreenshot(const Layout& l, bool last, std::string& error) {
  const render::GlApi& g = render::gl();
  g.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  g.ReadBuffer(GL_BACK);
  const std::string png = headless::encodePng(render::readFramebufferRgba(l.fbW, l.fbH), l.fbW, l.fbH);
  const std::string path = last && request_.screenshot ? *request_.screenshot : "kerf-screenshot.png";
  std::string writeError;
  if (png.empty() || !cli::writeOutput(path, request_.inputs, png, writeError)) {
    error = "cannot write the screenshot '" + path + "': " + (png.empty() ? "PNG encoding failed" : writeError);
    return false;
  }
  std::cerr << "kerf: wrote the window (" << l.fbW << "x" << l.fbH << ") to " << path << "\n";
  return true;
}

bool FrameLoop::frame(std::string& error, bool& failed) {
  const auto t0 = std::chrono::steady_clock::now();
  glfwPollEvents();
  const Layout l = layout();
  if (l.fbW <= 0 || l.fbH <= 0) return true;
  if ((l.viewW != targetW_ || l.viewH != targetH_) && !fitView(l, error)) {
    failed = true;
    return false;
  }
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  bool screenshot = false;
  textPanel(s_, l.textW, static_cast<float>(l.fbH));
  sidePanel(s_, static_cast<float>(l.fbW) - l.sideW, l.sideW, static_cast<float>(l.fbH), screenshot);
  showPasses();
  const bool moving = handleMouse(l);
  advancePlayback();
  stepWithKeys();
  construct();
  render::RenderOptions options = s_.options;
  options.selectedMove = s_.selected;
  annotate(options, l);  // the annotations of the picture, in the view's area
  ImGui::Render();

  render::Renderer& drawing = drawView(options, moving, l);
  const render::GlApi& g = render::gl();
  g.BindFramebuffer(GL_FRAMEBUFFER, 0);
  g.Viewport(0, 0, l.fbW, l.fbH);
  g.ClearColor(0.94f, 0.94f, 0.94f, 1.0f);
  g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  target_.resolveTo(0, l.viewX, 0);
  drawing.drawOverlay(ui::convertDrawData(*ImGui::GetDrawData()), l.fbW, l.fbH);
  ++frame_;
  const bool last = request_.frames > 0 && frame_ >= request_.frames;
  if ((screenshot || (last && request_.screenshot)) && !saveScreenshot(l, last, error)) failed = true;
  if (request_.benchmark) g.Finish();
  glfwSwapBuffers(window_);
  frameSeconds_.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return !last && !failed;
}

void FrameLoop::reportFrameTimes() const {
  if (!request_.benchmark || frameSeconds_.size() <= 1) return;
  std::vector<double> sorted(frameSeconds_.begin() + 1, frameSeconds_.end());  // the first frame uploads
  std::sort(sorted.begin(), sorted.end());
  double sum = 0;
  for (double v : sorted) sum += v;
  const double mean = sum / static_cast<double>(sorted.size());
  const double median = sorted[sorted.size() / 2], worst = sorted[sorted.size() - 1];
  const bool coarseShown = coarse_.has_value() && request_.coarseFrames;
  const std::size_t drawn = coarseShown ? coarse_.value().triangles() : request_.scene->triangles();
  std::fprintf(
      stderr,
      "kerf view: %zu frames, %zu triangles%s, frame time mean %.1f ms, median %.1f ms, max %.1f ms (%.1f fps)\n",
      sorted.size(), drawn, coarseShown ? " (coarse level)" : "", mean * 1e3, median * 1e3, worst * 1e3, 1.0 / mean);
}

}  // namespace

bool runWindow(const WindowRequest& request, std::string& error) {
  GLFWwindow* window = openWindow(request, error);
  if (!window) return false;
  bool ok = render::loadGl(&glfwLoader, error);
  State s;
  startState(s, request);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.BackendRendererName = "kerf::render";
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  ImGui::StyleColorsLight();
  glfwSetKeyCallback(window, onKey);  // before ImGui's backend, which calls it from its own
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  {
    FrameLoop loop(request, window, s);  // its GL objects go before the context
    if (ok) ok = loop.init(error);
    bool failed = false;
    while (ok && !glfwWindowShouldClose(window) && loop.frame(error, failed)) {
    }
    if (failed) ok = false;
    loop.reportFrameTimes();
  }
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return ok;
}

}  // namespace kerf::window
