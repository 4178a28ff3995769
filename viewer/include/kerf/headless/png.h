// PNG encoding of RGBA images (stb_image_write, Debian's libstb). Deterministic: the same pixels
// give the same bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::headless {

/// rgba: width * height * 4 bytes, rows top to bottom. Empty string on failure.
std::string encodePng(const std::vector<std::uint8_t>& rgba, int width, int height);

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< rows top to bottom
};
/// Decodes a PNG held in memory (any channel count becomes RGBA); nothing if it is not one.
std::optional<Image> decodePng(const std::string& bytes);

}  // namespace kerf::headless
