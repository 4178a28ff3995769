// kerf_image_compare EXPECTED.png ACTUAL.png [--threshold T] [--diff DIFF.png]
// Prints the SSIM error (tests/image/ssim.h) and exits 0 when it is at most the threshold,
// 1 when it is above (writing the diff image if asked), 2 when a file cannot be read.
#include "kerf/headless/png.h"
#include "ssim.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {
std::string readAll(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  ok = static_cast<bool>(in) || in.eof();
  return s.str();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: kerf_image_compare EXPECTED.png ACTUAL.png [--threshold T] [--diff DIFF.png]\n";
    return 2;
  }
  double threshold = 0.05;
  std::string diffPath;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--threshold") threshold = std::strtod(argv[i + 1], nullptr);
    if (key == "--diff") diffPath = argv[i + 1];
  }
  bool ok1 = false, ok2 = false;
  const auto expected = kerf::headless::decodePng(readAll(argv[1], ok1));
  const auto actual = kerf::headless::decodePng(readAll(argv[2], ok2));
  if (!expected || !actual) {
    std::cerr << "kerf_image_compare: cannot read " << (!expected ? argv[1] : argv[2]) << " as PNG\n";
    return 2;
  }
  const kerf::test::ImageView a{expected->width, expected->height, &expected->rgba};
  const kerf::test::ImageView b{actual->width, actual->height, &actual->rgba};
  const kerf::test::SsimResult r = kerf::test::compareImages(a, b);
  if (expected->width != actual->width || expected->height != actual->height) {
    std::cout << "size differs: expected " << expected->width << "x" << expected->height << ", got " << actual->width
              << "x" << actual->height << "\n";
    return 1;
  }
  std::printf("SSIM error %.4f (threshold %.4f), worst tile at %d,%d; mean SSIM %.5f\n", r.error, threshold,
              r.worstTileX, r.worstTileY, r.meanSsim);
  if (r.error <= threshold) return 0;
  if (!diffPath.empty()) {
    const std::string png = kerf::headless::encodePng(kerf::test::diffImage(a, r), a.width, a.height);
    std::ofstream(diffPath, std::ios::binary) << png;
  }
  return 1;
}
