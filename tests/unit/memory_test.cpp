// The large arrays' memory (geometry/memory.h): what is written is kept, through growth, copies and
// pages given back; a large block starts on a 2 MiB page of its own where the pages are ours.
#include "kerf/geometry/memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace kerf::geometry {
namespace {

std::uint64_t value(std::uint64_t k) { return k * 2654435761ULL + 7; }

TEST(memory, a_large_vector_keeps_what_it_holds_through_growth_and_copies) {
  LargeVector<std::uint64_t> v;  // grows through small blocks (operator new) into large ones
  for (std::uint64_t k = 0; k < (3u << 20); ++k) v.push_back(value(k));
  for (std::uint64_t k = 0; k < v.size(); k += 997) ASSERT_EQ(v[k], value(k));
  const LargeVector<std::uint64_t> copy = v;
  EXPECT_EQ(copy, v);
  v.resize(100);  // shrink_to_fit: from a large block back to a small one
  v.shrink_to_fit();
  for (std::uint64_t k = 0; k < v.size(); ++k) ASSERT_EQ(v[k], value(k));
  EXPECT_EQ(copy[(3u << 20) - 1], value((3u << 20) - 1));
}

TEST(memory, a_large_block_starts_on_a_huge_page_when_the_pages_are_ours) {
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  for (const std::size_t bytes : {kLargeBlock - 8, kLargeBlock, kHuge, kHuge + 1, 5 * kHuge + 12345}) {
    auto* p = static_cast<unsigned char*>(allocateLarge(bytes));
    ASSERT_NE(p, nullptr);
    if (largePagesOwned() && bytes >= kLargeBlock)
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % kHuge, 0u) << bytes;
    else
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % __STDCPP_DEFAULT_NEW_ALIGNMENT__, 0u) << bytes;
    p[0] = 1;  // both ends are writable
    p[bytes - 1] = 2;
    EXPECT_EQ(p[0] + p[bytes - 1], 3);
    freeLarge(p, bytes);
  }
}

TEST(memory, fill_later_resize_keeps_the_elements_before_and_push_back_constructs) {
  struct Pair {
    double a;
    int b;
  };
  std::vector<Pair, FillLaterAllocator<Pair>> v;
  v.push_back({1.5, 2});
  v.resize(1u << 18);  // 4 MiB: the new elements are left for their maker
  for (std::size_t k = 1; k < v.size(); ++k) v[k] = {static_cast<double>(k), static_cast<int>(k)};
  EXPECT_EQ(v[0].a, 1.5);
  EXPECT_EQ(v[0].b, 2);
  EXPECT_EQ(v.back().b, static_cast<int>(v.size() - 1));
  v.push_back({-1.0, -1});
  EXPECT_EQ(v.back().b, -1);
  EXPECT_EQ(v[12345].a, 12345.0);
}

// Pages given back inside a large block read as zeros; those outside the range keep their values.
TEST(memory, released_pages_of_a_large_block_read_as_zeros) {
  LargeVector<std::uint64_t> v(3u << 20);
  for (std::uint64_t k = 0; k < v.size(); ++k) v[k] = value(k);
  releasePages(v.data() + 1000, v.data() + 900000);
  EXPECT_EQ(v[999], value(999));
  EXPECT_EQ(v[500000], 0u);
  EXPECT_EQ(v[900000], value(900000));
  EXPECT_EQ(v[2000000], value(2000000));
}

}  // namespace
}  // namespace kerf::geometry
