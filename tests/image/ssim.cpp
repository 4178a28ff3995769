#include "ssim.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kerf::test {

namespace {

/// One colour channel (0 red, 1 green, 2 blue) as floats.
std::vector<float> channel(const ImageView& v, std::size_t c) {
  std::vector<float> y(static_cast<std::size_t>(v.width) * v.height);
  const auto& p = *v.rgba;
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = p[4 * i + c];
  return y;
}

/// Separable Gaussian blur (11 taps, sigma 1.5), edges clamped.
std::vector<float> blur(const std::vector<float>& in, int w, int h) {
  std::array<float, 11> k{};
  float sum = 0;
  for (int i = 0; i < 11; ++i) {
    const float x = static_cast<float>(i - 5);
    k[static_cast<std::size_t>(i)] = std::exp(-x * x / (2.0f * 1.5f * 1.5f));
    sum += k[static_cast<std::size_t>(i)];
  }
  for (float& v : k) v /= sum;
  std::vector<float> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float acc = 0;
      for (int i = -5; i <= 5; ++i)
        acc += k[static_cast<std::size_t>(i + 5)] * in[static_cast<std::size_t>(y) * w + std::clamp(x + i, 0, w - 1)];
      tmp[static_cast<std::size_t>(y) * w + x] = acc;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float acc = 0;
      for (int i = -5; i <= 5; ++i)
        acc += k[static_cast<std::size_t>(i + 5)] * tmp[static_cast<std::size_t>(std::clamp(y + i, 0, h - 1)) * w + x];
      out[static_cast<std::size_t>(y) * w + x] = acc;
    }
  return out;
}

}  // namespace

SsimResult compareImages(const ImageView& a, const ImageView& b) {
  SsimResult r;
  if (a.width != b.width || a.height != b.height || a.width <= 0 || a.height <= 0) return r;
  const int w = a.width, h = a.height;
  // Per channel, the worst at each pixel: a change of colour that keeps the brightness (red for
  // blue of the same luma) is a change.
  r.map.assign(static_cast<std::size_t>(w) * h, 1.0f);
  for (std::size_t c = 0; c < 3; ++c) {
    const std::vector<float> x = channel(a, c), y = channel(b, c);
    std::vector<float> xx(x.size()), yy(x.size()), xy(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      xx[i] = x[i] * x[i];
      yy[i] = y[i] * y[i];
      xy[i] = x[i] * y[i];
    }
    const std::vector<float> mx = blur(x, w, h), my = blur(y, w, h);
    const std::vector<float> sxx = blur(xx, w, h), syy = blur(yy, w, h), sxy = blur(xy, w, h);
    constexpr double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double ux = mx[i], uy = my[i];
      const double vx = std::max(0.0, static_cast<double>(sxx[i]) - ux * ux);
      const double vy = std::max(0.0, static_cast<double>(syy[i]) - uy * uy);
      const double cov = static_cast<double>(sxy[i]) - ux * uy;
      const double ssim = ((2 * ux * uy + c1) * (2 * cov + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
      r.map[i] = std::min(r.map[i], static_cast<float>(ssim));
    }
  }
  double total = 0;
  for (const float v : r.map) total += static_cast<double>(v);
  r.meanSsim = total / static_cast<double>(r.map.size());
  r.error = 0;
  for (int ty = 0; ty < h; ty += kSsimTile)
    for (int tx = 0; tx < w; tx += kSsimTile) {
      double sum = 0;
      int n = 0;
      for (int yy0 = ty; yy0 < std::min(h, ty + kSsimTile); ++yy0)
        for (int xx0 = tx; xx0 < std::min(w, tx + kSsimTile); ++xx0, ++n)
          sum += static_cast<double>(r.map[static_cast<std::size_t>(yy0) * w + xx0]);
      const double e = 1.0 - sum / n;
      if (e > r.error) {
        r.error = e;
        r.worstTileX = tx;
        r.worstTileY = ty;
      }
    }
  return r;
}

std::vector<std::uint8_t> diffImage(const ImageView& expected, const SsimResult& result) {
  std::vector<std::uint8_t> out(*expected.rgba);
  if (result.map.size() * 4 != out.size()) return out;
  for (std::size_t i = 0; i < result.map.size(); ++i) {
    const bool differs = result.map[i] < 0.98f;
    for (int c = 0; c < 3; ++c) {
      const auto faded = static_cast<std::uint8_t>(200 + out[4 * i + static_cast<std::size_t>(c)] / 5);
      out[4 * i + static_cast<std::size_t>(c)] = differs ? (c == 0 ? 255 : static_cast<std::uint8_t>(0)) : faded;
    }
    out[4 * i + 3] = 255;
  }
  return out;
}

}  // namespace kerf::test
