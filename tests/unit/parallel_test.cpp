// geometry/parallel.h: every index once, whatever the split; the worker count the program sets.
#include "kerf/geometry/parallel.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace {

using kerf::geometry::parallelFor;
using kerf::geometry::workerCount;
using Threads = kerf::test::ScopedThreads;

TEST(parallel_test, every_index_once_whatever_the_split) {
  const Threads t(4);
  for (const std::size_t n : {0u, 1u, 7u, 100u, 4097u, 100000u}) {
    for (const std::size_t chunk : {1u, 16u, 2048u}) {
      std::vector<std::atomic<int>> seen(n);
      std::atomic<int> calls{0};
      parallelFor(n, chunk, [&](std::size_t b, std::size_t e) {
        ASSERT_LT(b, e);
        ASSERT_GE(e - b, std::min(chunk, n));
        ++calls;
        for (std::size_t i = b; i < e; ++i) ++seen[i];
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " chunk " << chunk << " i " << i;
      EXPECT_LE(calls.load(), 16);  // at most four pieces a worker
      if (n > 0 && n < 2 * chunk) {
        EXPECT_EQ(calls.load(), 1);
      }
    }
  }
}

TEST(parallel_test, the_count_the_program_sets_is_the_threads_used) {
  const std::thread::id caller = std::this_thread::get_id();
  auto otherThreads = [&] {
    std::vector<std::thread::id> ids(4);
    parallelFor(4, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ids[i] = std::this_thread::get_id();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // so that no thread takes two
    });
    std::sort(ids.begin(), ids.end());
    return std::unique(ids.begin(), ids.end()) - ids.begin() - (std::count(ids.begin(), ids.end(), caller) > 0);
  };
  {
    const Threads t(4);
    EXPECT_EQ(workerCount(), 4u);
    EXPECT_GE(otherThreads(), 1);
  }
  {
    const Threads t(1);
    EXPECT_EQ(workerCount(), 1u);
    EXPECT_EQ(otherThreads(), 0);
  }
  {
    const Threads t(0);  // clamped: at least the calling thread
    EXPECT_EQ(workerCount(), 1u);
  }
}

TEST(parallel_test, sort_gives_what_std_sort_gives) {
  // Chunks sorted on their own then merged: the same order as one sort (keys with ties, compared
  // by key only: the multiset of each key's values must match too).
  std::uint64_t state = 12345;
  auto next = [&] { return state = state * 6364136223846793005ULL + 1442695040888963407ULL; };
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    const Threads t(threads);
    for (const std::size_t n : {0u, 5u, 1000u, 70000u, 300001u}) {
      std::vector<std::pair<int, int>> v(n);
      for (auto& [key, value] : v) {
        key = static_cast<int>(next() >> 52);  // 4096 keys: many ties
        value = static_cast<int>(next() >> 40);
      }
      auto byKey = [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; };
      std::vector<std::pair<int, int>> expect = v;
      std::sort(expect.begin(), expect.end());
      kerf::geometry::parallelSort(v.begin(), v.end(), byKey, 1024);
      ASSERT_TRUE(std::is_sorted(v.begin(), v.end(), byKey)) << threads << " threads, n " << n;
      std::sort(v.begin(), v.end());  // within each key, the same values
      ASSERT_EQ(v, expect) << threads << " threads, n " << n;
    }
  }
}

TEST(parallel_test, an_exception_reaches_the_caller_after_every_thread_ends) {
  const Threads t(4);
  std::atomic<int> running{0}, finished{0};
  EXPECT_THROW(parallelFor(4, 1,
                           [&](std::size_t b, std::size_t) {
                             ++running;
                             if (b == 2) throw std::runtime_error("piece 2");
                             std::this_thread::sleep_for(std::chrono::milliseconds(20));
                             ++finished;
                           }),
               std::runtime_error);
  // Every piece that started has ended by the time the exception reaches here.
  EXPECT_EQ(finished.load(), running.load() - 1);
}

TEST(parallel_test, a_call_from_inside_a_body_runs_in_its_thread) {
  const Threads t(3);
  constexpr std::size_t kOuter = 6, kInner = 50;
  std::vector<std::atomic<int>> seen(kOuter * kInner);
  parallelFor(kOuter, 1, [&](std::size_t b, std::size_t e) {
    const std::thread::id outer = std::this_thread::get_id();
    for (std::size_t o = b; o < e; ++o)
      parallelFor(kInner, 1, [&](std::size_t ib, std::size_t ie) {
        EXPECT_EQ(std::this_thread::get_id(), outer);
        for (std::size_t i = ib; i < ie; ++i) ++seen[o * kInner + i];
      });
  });
  for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i].load(), 1) << i;
}

}  // namespace
