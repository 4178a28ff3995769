// 2D overlay geometry in pixels: textured, coloured triangles with a clip rectangle per command.
// The layout of OverlayVertex is the one of Dear ImGui's ImDrawVert (pos, uv, packed colour), so
// ImGui draw lists convert by copying; the renderer itself knows nothing of ImGui.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace kerf::render {

struct OverlayVertex {
  float x, y;            ///< pixels, origin top left
  float u, v;            ///< in the font texture
  std::uint32_t colour;  ///< 0xAABBGGRR
};

struct OverlayCommand {
  std::array<float, 4> clip;  ///< x0, y0, x1, y1 in pixels
  std::uint32_t firstIndex = 0;
  std::uint32_t indexCount = 0;
};

struct OverlayDrawData {
  std::vector<OverlayVertex> vertices;
  std::vector<std::uint32_t> indices;  ///< into vertices
  std::vector<OverlayCommand> commands;
};

}  // namespace kerf::render
