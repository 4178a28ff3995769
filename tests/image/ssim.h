// The snapshot tests' image error: structural similarity (SSIM, Wang et al. 2004) of two images,
// per colour channel (the worst of red, green and blue at each pixel, so a change of colour at the
// same brightness counts), with an 11x11 Gaussian window (sigma 1.5) and the paper's constants
// C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2.
//
// A mean over the whole picture hides a small local change (a missing marker in a mostly white
// picture), so the error is taken per tile: error = max over 32x32-pixel tiles of
// (1 - mean SSIM in the tile). Scale (measured, docs/rendering.md): 0 identical; about 0.01 for
// the same scene rendered one pixel to the side; 0.2 and up for a missing marker or a changed colour.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace kerf::test {

struct ImageView {
  int width = 0, height = 0;
  const std::vector<std::uint8_t>* rgba = nullptr;  ///< rows top to bottom
};

struct SsimResult {
  double error = 1.0;                  ///< max over tiles of 1 - mean SSIM; 1 when the sizes differ
  double meanSsim = 0.0;               ///< over the whole picture
  int worstTileX = 0, worstTileY = 0;  ///< pixels, top left of the worst tile
  std::vector<float> map;              ///< SSIM per pixel (empty when the sizes differ)
};

inline constexpr int kSsimTile = 32;

SsimResult compareImages(const ImageView& a, const ImageView& b);

/// A picture of where the images differ: the expected image faded, pixels with SSIM below 0.98 in red.
std::vector<std::uint8_t> diffImage(const ImageView& expected, const SsimResult& result);

}  // namespace kerf::test
