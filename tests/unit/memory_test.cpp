// The large arrays' memory (geometry/memory.h): what is written is kept, through growth, copies and
// pages given back; a large block starts on a 2 MiB page of its own where the pages are ours.
#include "kerf/geometry/memory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

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

#if defined(__linux__)
constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// How many of the small pages of the 2 MiB page at p are in memory.
std::size_t residentIn(const void* p) {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> state(kHugePage / page);
  if (mincore(const_cast<void*>(p), kHugePage, state.data()) != 0) return 0;
  std::size_t n = 0;
  for (const unsigned char s : state) n += s & 1u;
  return n;
}

/// Holds what the pool has parked (earlier tests leave pages there) in a block of its own, so
/// that a test counts only its own pages.
struct Drained {
  Drained() : bytes((parkedPages() + 1) * kHugePage), block(allocateLarge(bytes)) {}
  Drained(const Drained&) = delete;
  Drained& operator=(const Drained&) = delete;
  ~Drained() { freeLarge(block, bytes); }
  std::size_t bytes;
  void* block;
};

bool poolOn() {
  const char* env = std::getenv("KERF_PAGE_POOL");
  return largePagesOwned() && !(env && std::strcmp(env, "0") == 0);
}

// A freed block's pages, written in full, are moved into the next block instead of fresh ones:
// the new block's first page is in memory before anything writes it, and holds what it is given.
TEST(memory, a_freed_block_s_written_pages_go_to_the_next_block) {
  if (!poolOn()) GTEST_SKIP() << "the pages are not Kerf's own here (AddressSanitizer, or KERF_PAGE_POOL=0)";
  const Drained drained;
  ASSERT_EQ(parkedPages(), 0u);
  constexpr std::size_t kBytes = 4 * kHugePage;
  auto* a = static_cast<std::uint64_t*>(allocateLarge(kBytes));
  for (std::size_t k = 0; k < kBytes / 8; ++k) a[k] = value(k);
  const std::size_t before = parkedPages();
  freeLarge(a, kBytes);
  ASSERT_EQ(parkedPages(), before + 4);
  auto* b = static_cast<std::uint64_t*>(allocateLarge(kBytes + kHugePage));
  EXPECT_EQ(parkedPages(), before);  // all four taken
  EXPECT_EQ(residentIn(b), kHugePage / static_cast<std::size_t>(sysconf(_SC_PAGESIZE)));
  EXPECT_EQ(residentIn(reinterpret_cast<char*>(b) + 4 * kHugePage), 0u);  // the fifth is fresh
  for (std::size_t k = 0; k < (kBytes + kHugePage) / 8; ++k) b[k] = ~value(k);
  for (std::size_t k = 0; k < (kBytes + kHugePage) / 8; k += 4099) ASSERT_EQ(b[k], ~value(k));
  freeLarge(b, kBytes + kHugePage);
}

// Pages given back inside a block in use read as zeros, and are adopted where a block says it
// writes next; a page only partly written is not parked (it would bring stale bytes with it, and
// gives little), and nothing is adopted outside Kerf's blocks or onto pages already written.
TEST(memory, given_back_pages_read_as_zeros_and_are_adopted_where_a_block_writes_next) {
  if (!poolOn()) GTEST_SKIP() << "the pages are not Kerf's own here (AddressSanitizer, or KERF_PAGE_POOL=0)";
  const Drained drained;
  ASSERT_EQ(parkedPages(), 0u);
  const auto words = kHugePage / 8;
  LargeVector<std::uint64_t> v(5 * words);
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = value(k);
  const std::size_t before = parkedPages();
  releasePages(v.data() + 10, v.data() + 3 * words + 10);  // pages 1 and 2 whole
  EXPECT_EQ(parkedPages(), before + 2);
  EXPECT_EQ(v[words], 0u);
  EXPECT_EQ(v[3 * words - 1], 0u);
  EXPECT_EQ(v[3 * words + 10], value(3 * words + 10));
  EXPECT_EQ(v[9], value(9));
  v[words + 5] = 77;  // the hole is ordinary memory
  EXPECT_EQ(v[words + 5], 77u);

  std::vector<std::uint64_t, FillLaterAllocator<std::uint64_t>> w;
  w.reserve(4 * words);
  const std::size_t taken0 = parkedPages();
  EXPECT_EQ(taken0, 0u) << "the new block took the two pages when it was made";
  w.resize(words / 2);
  for (std::size_t k = 0; k < w.size(); ++k) w[k] = k;
  freeLarge(allocateLarge(kHugePage), kHugePage);  // an untouched block: nothing to park
  EXPECT_EQ(parkedPages(), 0u);
  // The first page of w is written: adopting over it is refused, whatever the pool holds.
  LargeVector<std::uint64_t> x(words);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = k;
  x = LargeVector<std::uint64_t>();
  EXPECT_EQ(parkedPages(), 1u);
  EXPECT_EQ(adoptPages(w.data(), w.data() + words), 0u);
  std::vector<std::uint64_t> ordinary(3 * words);
  EXPECT_EQ(adoptPages(ordinary.data(), ordinary.data() + ordinary.size()), 0u);
  w.resize(4 * words);
  for (std::size_t k = words / 2; k < w.size(); ++k) w[k] = k;
  for (std::size_t k = 0; k < w.size(); k += 1021) ASSERT_EQ(w[k], k);
}

// In small pages (the default: KERF_HUGE_PAGES unset), a 2 MiB page written in part, as where a
// text or an array ends, is parked when at least a quarter of it is written, and carries what was
// written; less is given to the system.
TEST(memory, a_page_written_in_part_is_parked_from_a_quarter_on) {
  if (!poolOn()) GTEST_SKIP() << "the pages are not Kerf's own here (AddressSanitizer, or KERF_PAGE_POOL=0)";
  const char* huge = std::getenv("KERF_HUGE_PAGES");
  if (huge && std::strcmp(huge, "1") == 0) GTEST_SKIP() << "in huge pages a page is written whole or not at all";
  const Drained drained;
  const auto words = kHugePage / 8;
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  auto* a = static_cast<std::uint64_t*>(allocateLarge(2 * kHugePage));
  for (std::size_t k = 0; k < words / 2; ++k) a[k] = value(k);  // half of the first page
  a[words] = 1;                                                 // a few bytes of the second
  ASSERT_EQ(residentIn(a), kHugePage / page / 2);
  ASSERT_EQ(residentIn(a + words), 1u);
  const std::size_t before = parkedPages();
  freeLarge(a, 2 * kHugePage);
  EXPECT_EQ(parkedPages(), before + 1) << "the half-written page parked, the nearly empty one not";
  auto* b = static_cast<std::uint64_t*>(allocateLarge(kHugePage));
  EXPECT_EQ(parkedPages(), before);
  EXPECT_EQ(residentIn(b), kHugePage / page / 2) << "the parked page's written half came with it";
  for (std::size_t k = 0; k < words; ++k) b[k] = ~value(k);
  for (std::size_t k = 0; k < words; k += 1021) ASSERT_EQ(b[k], ~value(k));
  freeLarge(b, kHugePage);
}

// movePages moves whole pages between Kerf's blocks without copying: the bytes arrive, the place
// they left reads as zeros, and a page already at the target is parked rather than lost. It
// refuses (nothing moved) what it cannot do: unaligned places, overlapping ranges, memory that is
// not Kerf's own.
TEST(memory, pages_move_between_blocks_whole_and_the_place_they_left_reads_as_zeros) {
  if (!poolOn()) GTEST_SKIP() << "the pages are not Kerf's own here (AddressSanitizer, or KERF_PAGE_POOL=0)";
  const Drained drained;
  const auto words = kHugePage / 8;
  LargeVector<std::uint64_t> from(2 * words + 100);
  for (std::size_t k = 0; k < from.size(); ++k) from[k] = value(k);
  std::vector<std::uint64_t, FillLaterAllocator<std::uint64_t>> to;
  to.reserve(6 * words);
  to.resize(words / 2);
  for (std::size_t k = 0; k < to.size(); ++k) to[k] = ~value(k);
  // A page at the target already written: parked, not dropped (written whole: in small pages a
  // 2 MiB page written in a quarter or less is given to the system instead).
  std::fill_n(to.data() + 3 * words, words, std::uint64_t{5});
  const std::size_t parked = parkedPages();
  ASSERT_TRUE(movePages(to.data() + 2 * words, from.data(), from.size() * 8));
  EXPECT_EQ(parkedPages(), parked + 1);
  to.resize(2 * words + from.size());
  for (std::size_t k = 0; k < from.size(); ++k) ASSERT_EQ(to[2 * words + k], value(k)) << k;
  for (std::size_t k = 0; k < words / 2; ++k) ASSERT_EQ(to[k], ~value(k)) << k;
  for (std::size_t k = 0; k < from.size(); k += 997) ASSERT_EQ(from[k], 0u) << k;
  from[7] = 9;  // what is left is ordinary memory
  EXPECT_EQ(from[7], 9u);

  EXPECT_FALSE(movePages(to.data() + 1, from.data(), 8)) << "not on a 2 MiB boundary";
  EXPECT_FALSE(movePages(to.data() + words, to.data(), 2 * words * 8)) << "overlapping";
  EXPECT_FALSE(movePages(to.data() + 5 * words, from.data(), 3 * words * 8)) << "past the end of the target block";
  std::vector<std::uint64_t> ordinary(3 * words);
  EXPECT_FALSE(movePages(ordinary.data(), from.data(), 8)) << "not Kerf's own";
  EXPECT_EQ(from[7], 9u);
}
#endif

}  // namespace
}  // namespace kerf::geometry
