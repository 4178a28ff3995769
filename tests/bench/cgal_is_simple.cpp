// The peer for Kerf's self-intersection on star polygons (tests/bench/compare.sh): CGAL's
// is_simple_2 (Shamos-Hoey over the polygon's edges, exact predicates) on the same vertices Kerf
// reads. Built by compare.sh only, against Debian's libcgal-dev; not part of the Kerf build.
//   cgal_is_simple N    the star of kerf_bench --shape star --blocks N (radii 100 and 40 mm,
//                       rounded to 4 decimals as the program writes them)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
  std::vector<K::Point_2> pts;
  pts.reserve(static_cast<std::size_t>(n));
  // The vertices in the program's order: start (100, 0), then i = 1 .. n-1 (the last block returns
  // to the start, which closes the polygon).
  pts.emplace_back(100.0, 0.0);
  for (long i = 1; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    const double r = i % 2 ? 40.0 : 100.0;
    pts.emplace_back(std::round(r * std::cos(a) * 1e4) / 1e4, std::round(r * std::sin(a) * 1e4) / 1e4);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool simple = CGAL::is_simple_2(pts.begin(), pts.end(), K());
  const auto t1 = std::chrono::steady_clock::now();
  std::printf("cgal is_simple_2: %.6f s  %ld vertices  %s\n", std::chrono::duration<double>(t1 - t0).count(), n,
              simple ? "simple" : "not simple");
  return simple ? 0 : 1;
}
