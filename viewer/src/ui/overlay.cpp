#include "ui/overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace kerf::ui {

namespace {

constexpr ImU32 kText = IM_COL32(20, 20, 25, 255);
constexpr ImU32 kPanel = IM_COL32(255, 255, 255, 210);

/// The surface shader's ramp (shaders/surface.frag), for the legend.
/// The slope and deviation ramp (render::rampColour, 0xAABBGGRR as ImGui's IM_COL32).
ImU32 rampColour(float x) { return render::rampColour(x); }

void textWithBackground(ImDrawList& list, ImVec2 at, ImU32 colour, const char* text) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  list.AddRectFilled(ImVec2(at.x - 2, at.y - 1), ImVec2(at.x + size.x + 2, at.y + size.y + 1), kPanel, 2.0f);
  list.AddText(at, colour, text);
}

/// Whether a label of `size` at `at` stays in the picture and covers no box in `placed`; if so its
/// box joins them.
bool placeLabel(std::vector<ImVec4>& placed, ImVec2 at, ImVec2 size, int width, int height) {
  const ImVec4 box(at.x - 2, at.y - 1, at.x + size.x + 2, at.y + size.y + 1);
  const bool inside =
      box.x >= 0 && box.y >= 0 && box.z <= static_cast<float>(width) && box.w <= static_cast<float>(height);
  const bool covers = std::any_of(placed.begin(), placed.end(), [&](const ImVec4& o) {
    return box.x < o.z && o.x < box.z && box.y < o.w && o.y < box.w;
  });
  if (!inside || covers) return false;
  placed.push_back(box);
  return true;
}

std::string formatNumber(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// The ramp as a bar from (x0, y0), w wide and h tall: its red end at the top.
void rampBar(ImDrawList& list, float x0, float y0, float w, float h) {
  constexpr int kSteps = 16;
  for (int i = 0; i < kSteps; ++i) {
    const float a = y0 + h * static_cast<float>(i) / kSteps, b = y0 + h * static_cast<float>(i + 1) / kSteps;
    const ImU32 top = rampColour(1.0f - static_cast<float>(i) / kSteps);
    const ImU32 bottom = rampColour(1.0f - static_cast<float>(i + 1) / kSteps);
    list.AddRectFilledMultiColor(ImVec2(x0, a), ImVec2(x0 + w, b), top, top, bottom, bottom);
  }
  list.AddRect(ImVec2(x0, y0), ImVec2(x0 + w, y0 + h), kText);
}

/// The slope legend at the right edge: the surface shader's ramp and the slopes at its ends.
void drawSlopeLegend(ImDrawList& list, const render::Scene& scene, int width, int height) {
  const float lineHeight = ImGui::GetTextLineHeight();
  const float barH = std::min(160.0f, static_cast<float>(height) * 0.45f), barW = 12.0f;
  const float x0 = static_cast<float>(width) - 92.0f, y0 = 30.0f;
  const std::string hi = formatNumber(scene.maxSlopeDegrees, 2) + " deg";
  const std::string lo = formatNumber(scene.minSlopeDegrees, 2) + " deg";
  list.AddRectFilled(ImVec2(x0 - 6, y0 - lineHeight - 8), ImVec2(static_cast<float>(width) - 4, y0 + barH + 6), kPanel,
                     2.0f);
  list.AddText(ImVec2(x0 - 2, y0 - lineHeight - 5), kText, "slope");
  rampBar(list, x0, y0, barW, barH);
  list.AddText(ImVec2(x0 + barW + 3, y0 - 2), kText, hi.c_str());
  list.AddText(ImVec2(x0 + barW + 3, y0 + barH - lineHeight + 2), kText, lo.c_str());
}

/// The deviation legend at the right edge: the ramp from 0 to the scale in µm, the tolerance marked.
void drawDeviationLegend(ImDrawList& list, double scaleUm, double toleranceUm, int width, int height) {
  const float lineHeight = ImGui::GetTextLineHeight();
  const float barH = std::min(160.0f, static_cast<float>(height) * 0.45f), barW = 12.0f;
  const float x0 = static_cast<float>(width) - 100.0f, y0 = 4.0f * lineHeight + 24.0f;  // under the title
  list.AddRectFilled(ImVec2(x0 - 6, y0 - 2 * lineHeight - 8), ImVec2(static_cast<float>(width) - 4, y0 + barH + 6),
                     kPanel, 2.0f);
  list.AddText(ImVec2(x0 - 2, y0 - 2 * lineHeight - 5), kText, "deviation");
  list.AddText(ImVec2(x0 - 2, y0 - lineHeight - 4), kText, "from drawing");
  rampBar(list, x0, y0, barW, barH);
  list.AddText(ImVec2(x0 + barW + 3, y0 - 2), kText, (formatNumber(scaleUm, 1) + " um").c_str());
  list.AddText(ImVec2(x0 + barW + 3, y0 + barH - lineHeight + 2), kText, "0 um");
  if (toleranceUm > 0 && toleranceUm < scaleUm) {  // the tolerance: a tick across the bar
    const float y = y0 + barH * static_cast<float>(1.0 - toleranceUm / scaleUm);
    list.AddLine(ImVec2(x0 - 3, y), ImVec2(x0 + barW + 3, y), kText, 2.0f);
    // Its label clear of the ends' labels: a tolerance near 0 or the top keeps the tick there.
    const float labelY = std::max(std::min(y - lineHeight / 2, y0 + barH - 2 * lineHeight + 1), y0 + lineHeight - 1);
    list.AddText(ImVec2(x0 + barW + 3, labelY), kText, ("tol " + formatNumber(toleranceUm, 1)).c_str());
  }
}

/// The pass legend at the right edge, under the title: a swatch in each pass's colour and its name.
void drawPassLegend(ImDrawList& list, const std::vector<std::string>& names, int width) {
  const float lineHeight = ImGui::GetTextLineHeight();
  float textW = 0.0f;
  for (const std::string& s : names) textW = std::max(textW, ImGui::CalcTextSize(s.c_str()).x);
  const float swatch = lineHeight * 0.8f, rowH = lineHeight + 3.0f;
  const float x0 = static_cast<float>(width) - textW - swatch - 16.0f, y0 = 2.0f * lineHeight + 14.0f;
  const float y1 = y0 + rowH * static_cast<float>(names.size());
  list.AddRectFilled(ImVec2(x0 - 6, y0 - 4), ImVec2(static_cast<float>(width) - 4, y1 + 2), kPanel, 2.0f);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const float row = y0 + rowH * static_cast<float>(k);
    const std::uint32_t c = render::passColour(k + 1);  // 0xAABBGGRR, as ImGui's IM_COL32
    list.AddRectFilled(ImVec2(x0, row + 2), ImVec2(x0 + swatch, row + 2 + swatch), c);
    list.AddText(ImVec2(x0 + swatch + 5, row), kText, names[k].c_str());
  }
}

/// The selected block's construction: each mark's label beside its anchor, in the mark's colour,
/// where it covers no label placed before it (four places tried: right above, right below, left
/// above, left below); the caption (the block, its words, its modes) in a box from `top` down at
/// the left.
void drawConstruction(ImDrawList& list, const render::ConstructionScene& c, const render::Camera& camera, int width,
                      int height, float top) {
  const float lineHeight = ImGui::GetTextLineHeight();
  std::vector<ImVec4> placed;
  if (!c.caption.empty()) {
    float w = 0.0f;
    for (const std::string& line : c.caption) w = std::max(w, ImGui::CalcTextSize(line.c_str()).x);
    const float h = static_cast<float>(c.caption.size()) * (lineHeight + 1);
    list.AddRectFilled(ImVec2(4, top - 2), ImVec2(12 + w, top + h + 2), kPanel, 2.0f);
    for (std::size_t k = 0; k < c.caption.size(); ++k)
      list.AddText(ImVec2(8, top + static_cast<float>(k) * (lineHeight + 1)), kText, c.caption[k].c_str());
    placed.emplace_back(4, top - 2, 12 + w, top + h + 2);
  }
  for (const render::Marker& m : c.labels) {
    const Eigen::Vector2d p = camera.project(m.position, width, height);
    const ImVec2 size = ImGui::CalcTextSize(m.label.c_str());
    const auto px = static_cast<float>(p.x()), py = static_cast<float>(p.y());
    for (const ImVec2 at : {ImVec2(px + 8, py - lineHeight - 2), ImVec2(px + 8, py + 4),
                            ImVec2(px - 8 - size.x, py - lineHeight - 2), ImVec2(px - 8 - size.x, py + 4)})
      if (placeLabel(placed, at, size, width, height)) {
        textWithBackground(list, at, m.colour | IM_COL32(0, 0, 0, 255), m.label.c_str());
        break;
      }
  }
}

}  // namespace

double niceLength(double maxLength) {
  if (!(maxLength > 0)) return 0;
  const double p = std::pow(10.0, std::floor(std::log10(maxLength)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= maxLength) return m * p;
  return p;
}

void drawAnnotations(ImDrawList& list, const render::Scene& scene, const render::Camera& camera,
                     const render::RenderOptions& options, const Annotation& annotation, int width, int height) {
  const float lineHeight = ImGui::GetTextLineHeight();
  // Title block, top left.
  float y = 6.0f;
  for (const std::string* line : {&annotation.title, &annotation.subtitle}) {
    if (line->empty()) continue;
    textWithBackground(list, ImVec2(8, y), kText, line->c_str());
    y += lineHeight + 3;
  }
  if (scene.truncated) {
    textWithBackground(list, ImVec2(8, y), IM_COL32(200, 0, 0, 255), "surface incomplete: triangle limit reached");
    y += lineHeight + 3;
  }

  // Scale bar, bottom right: a 1-2-5 length of at most a fifth of the width.
  const double mmPerPixel = camera.mmPerPixel(height);
  const double length = niceLength(0.2 * width * mmPerPixel);
  if (length > 0 && options.surface) {
    const auto px = static_cast<float>(length / mmPerPixel);
    const float x1 = static_cast<float>(width) - 12.0f, x0 = x1 - px, yb = static_cast<float>(height) - 12.0f;
    const std::string label = formatNumber(length, length < 1 ? (length < 0.1 ? 3 : 2) : 0) + " mm";
    const ImVec2 ls = ImGui::CalcTextSize(label.c_str());
    list.AddRectFilled(ImVec2(x0 - 4, yb - ls.y - 8), ImVec2(x1 + 4, yb + 4), kPanel, 2.0f);
    list.AddLine(ImVec2(x0, yb), ImVec2(x1, yb), kText, 2.0f);
    list.AddLine(ImVec2(x0, yb - 4), ImVec2(x0, yb + 2), kText, 1.0f);
    list.AddLine(ImVec2(x1, yb - 4), ImVec2(x1, yb + 2), kText, 1.0f);
    list.AddText(ImVec2(0.5f * (x0 + x1) - 0.5f * ls.x, yb - ls.y - 5), kText, label.c_str());
  }

  if (annotation.construction) drawConstruction(list, *annotation.construction, camera, width, height, y + 4);
  if (annotation.legend && options.colourBySlope && options.surface) drawSlopeLegend(list, scene, width, height);
  if (!annotation.passLegend.empty()) drawPassLegend(list, annotation.passLegend, width);
  if (annotation.deviationScaleUm > 0)
    drawDeviationLegend(list, annotation.deviationScaleUm, annotation.toleranceUm, width, height);

  // Finding labels beside their markers: errors first, each where it covers no label placed
  // before it and stays in the picture; what finds no place is counted under the title.
  if (annotation.labels && options.markers) {
    std::vector<const render::Marker*> order;
    for (const render::Marker& m : scene.findings) order.push_back(&m);
    std::stable_sort(order.begin(), order.end(),
                     [](const render::Marker* a, const render::Marker* b) { return a->severity > b->severity; });
    std::vector<ImVec4> placed;
    std::size_t labelled = 0;
    for (const render::Marker* m : order) {
      const Eigen::Vector2d p = camera.project(m->position, width, height);
      const ImVec2 at(static_cast<float>(p.x()) + 10, static_cast<float>(p.y()) - lineHeight - 2);
      if (!placeLabel(placed, at, ImGui::CalcTextSize(m->label.c_str()), width, height)) continue;
      if (m->severity != converter::Severity::Note) ++labelled;
      const ImU32 colour = m->severity == converter::Severity::Error     ? IM_COL32(190, 0, 0, 255)
                           : m->severity == converter::Severity::Warning ? IM_COL32(150, 90, 0, 255)
                                                                         : IM_COL32(20, 80, 180, 255);
      textWithBackground(list, at, colour, m->label.c_str());
    }
    if (annotation.findings > labelled) {
      const std::string more =
          "+" + std::to_string(annotation.findings - labelled) + " more errors and warnings: kerf check lists them";
      textWithBackground(list, ImVec2(8, y), IM_COL32(190, 0, 0, 255), more.c_str());
    }
  }

  // Triad letters.
  if (options.triad) {
    const render::TriadLayout t = render::triadLayout(camera, height);
    const char* names[3] = {"X", "Y", "Z"};
    const ImU32 colours[3] = {IM_COL32(200, 30, 30, 255), IM_COL32(30, 140, 30, 255), IM_COL32(30, 60, 210, 255)};
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector2d d = t.tips[i] - t.origin;
      if (d.norm() < 4) continue;  // seen end-on
      const Eigen::Vector2d at = t.tips[i] + 7.0 * d.normalized();
      list.AddText(ImVec2(static_cast<float>(at.x()) - 3, static_cast<float>(at.y()) - 0.5f * lineHeight), colours[i],
                   names[i]);
    }
  }
}

render::OverlayDrawData convertDrawData(const ImDrawData& data) {
  static_assert(sizeof(ImDrawVert) == sizeof(render::OverlayVertex), "ImDrawVert layout");
  static_assert(offsetof(ImDrawVert, pos) == offsetof(render::OverlayVertex, x), "ImDrawVert layout");
  static_assert(offsetof(ImDrawVert, uv) == offsetof(render::OverlayVertex, u), "ImDrawVert layout");
  static_assert(offsetof(ImDrawVert, col) == offsetof(render::OverlayVertex, colour), "ImDrawVert layout");
  render::OverlayDrawData out;
  const ImVec2 origin = data.DisplayPos;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const std::size_t firstVertex = out.vertices.size();
    out.vertices.resize(firstVertex + static_cast<std::size_t>(list.VtxBuffer.Size));
    if (list.VtxBuffer.Size > 0)
      std::memcpy(&out.vertices[firstVertex], list.VtxBuffer.Data,
                  static_cast<std::size_t>(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    for (std::size_t v = firstVertex; v < out.vertices.size(); ++v) {
      out.vertices[v].x -= origin.x;
      out.vertices[v].y -= origin.y;
    }
    for (int c = 0; c < list.CmdBuffer.Size; ++c) {
      const ImDrawCmd& cmd = list.CmdBuffer[c];
      if (cmd.UserCallback != nullptr) continue;
      render::OverlayCommand oc;
      oc.clip = {cmd.ClipRect.x - origin.x, cmd.ClipRect.y - origin.y, cmd.ClipRect.z - origin.x,
                 cmd.ClipRect.w - origin.y};
      oc.firstIndex = static_cast<std::uint32_t>(out.indices.size());
      oc.indexCount = cmd.ElemCount;
      for (unsigned i = 0; i < cmd.ElemCount; ++i)
        out.indices.push_back(base + cmd.VtxOffset + list.IdxBuffer[static_cast<int>(cmd.IdxOffset + i)]);
      out.commands.push_back(oc);
    }
  }
  return out;
}

HeadlessOverlay::HeadlessOverlay() {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(1)));
  ImGui::SetCurrentContext(previous ? previous : context_);
}

HeadlessOverlay::~HeadlessOverlay() { ImGui::DestroyContext(context_); }

void HeadlessOverlay::uploadFont(render::Renderer& renderer) {
  ImGui::SetCurrentContext(context_);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  renderer.setOverlayTexture(w, h, pixels);
}

render::OverlayDrawData HeadlessOverlay::frame(const render::Scene& scene, const render::Camera& camera,
                                               const render::RenderOptions& options, const Annotation& annotation,
                                               int width, int height) {
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 60.0f;
  ImGui::NewFrame();
  drawAnnotations(*ImGui::GetForegroundDrawList(), scene, camera, options, annotation, width, height);
  ImGui::Render();
  return convertDrawData(*ImGui::GetDrawData());
}

}  // namespace kerf::ui
