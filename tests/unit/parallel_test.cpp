#include "kerf/geometry/parallel.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using kerf::geometry::parallelFor;
using kerf::geometry::workerCount;

using Threads = kerf::test::ScopedThreads;

TEST(Parallel, EveryIndexOnceWhateverTheSplit) {
  const Threads t("4");
  for (const std::size_t n : {0u, 1u, 7u, 100u, 4097u, 100000u}) {
    for (const std::size_t chunk : {1u, 16u, 2048u}) {
      std::vector<std::atomic<int>> seen(n);
      std::atomic<int> calls{0};
      parallelFor(n, chunk, [&](std::size_t b, std::size_t e) {
        ASSERT_LT(b, e);
        ++calls;
        for (std::size_t i = b; i < e; ++i) ++seen[i];
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " chunk " << chunk << " i " << i;
      // Below two chunks' worth, one call in the calling thread; never more calls than workers.
      EXPECT_LE(calls.load(), 4);
      if (n > 0 && n < 2 * chunk) {
        EXPECT_EQ(calls.load(), 1);
      }
    }
  }
}

TEST(Parallel, BalancedEveryIndexOnceInPiecesOfAtLeastAChunkUpToFourAWorker) {
  for (const char* threads : {"1", "2", "4"}) {
    const Threads t(threads);
    const std::size_t workers = workerCount();
    for (const std::size_t n : {0u, 1u, 7u, 100u, 4097u, 100000u}) {
      for (const std::size_t chunk : {1u, 16u, 2048u}) {
        std::vector<std::atomic<int>> seen(n);
        std::atomic<std::size_t> pieces{0};
        kerf::geometry::parallelForBalanced(n, chunk, [&](std::size_t b, std::size_t e) {
          ASSERT_LT(b, e);
          ++pieces;
          // Every piece is a chunk or more, unless one call takes everything.
          if (e - b < n) {
            ASSERT_GE(e - b, chunk);
          }
          for (std::size_t i = b; i < e; ++i) ++seen[i];
        });
        for (std::size_t i = 0; i < n; ++i)
          ASSERT_EQ(seen[i].load(), 1) << "n " << n << " chunk " << chunk << " i " << i;
        EXPECT_LE(pieces.load(), std::max<std::size_t>(1, 4 * workers)) << threads;
        if (workers > 1 && n / chunk >= 4 * workers) {
          EXPECT_EQ(pieces.load(), 4 * workers) << threads << " n " << n;
        }
      }
    }
  }
  // A piece that throws: the call rethrows it once every worker has stopped.
  const Threads t("2");
  std::atomic<int> ran{0};
  EXPECT_THROW(kerf::geometry::parallelForBalanced(1000, 10,
                                                   [&](std::size_t b, std::size_t) {
                                                     ++ran;
                                                     if (b == 0) throw std::runtime_error("piece");
                                                   }),
               std::runtime_error);
  EXPECT_GE(ran.load(), 1);
}

TEST(Parallel, UsesOtherThreadsAndKerfThreadsOneIsSerial) {
  const std::thread::id caller = std::this_thread::get_id();
  auto threadsUsed = [&] {
    std::vector<std::thread::id> ids(4);
    parallelFor(4, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ids[i] = std::this_thread::get_id();
    });
    std::size_t others = 0;
    for (const auto& id : ids) others += id != caller;
    return others;
  };
  {
    const Threads t("4");
    EXPECT_EQ(workerCount(), 4u);
    EXPECT_EQ(threadsUsed(), 3u);  // the calling thread takes the first chunk
  }
  {
    const Threads t("1");
    EXPECT_EQ(workerCount(), 1u);
    EXPECT_EQ(threadsUsed(), 0u);
  }
  {
    const Threads t("none");  // not a number: the hardware's count, at least 1
    EXPECT_GE(workerCount(), 1u);
  }
}

TEST(Parallel, SortGivesWhatStdSortGives) {
  // Chunks sorted on their own then merged: the same order as one sort (keys with ties, compared
  // by key only: the multiset of each key's values must match too).
  std::uint64_t state = 12345;
  auto next = [&] { return state = state * 6364136223846793005ULL + 1442695040888963407ULL; };
  for (const char* threads : {"1", "2", "3", "8"}) {
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

TEST(Parallel, AnExceptionReachesTheCallerAfterEveryThreadEnds) {
  const Threads t("4");
  std::atomic<int> finished{0};
  EXPECT_THROW(parallelFor(4, 1,
                           [&](std::size_t b, std::size_t) {
                             if (b == 2) throw std::runtime_error("chunk 2");
                             ++finished;
                           }),
               std::runtime_error);
  EXPECT_EQ(finished.load(), 3);
}

TEST(Parallel, InvokeRunsBothOnceAndTogetherWhenThereAreTwoWorkers) {
  for (const char* threads : {"1", "2", "4"}) {
    const Threads t(threads);
    std::atomic<int> first{0}, second{0};
    std::thread::id firstOn, secondOn;
    kerf::geometry::parallelInvoke(
        [&] {
          ++first;
          firstOn = std::this_thread::get_id();
        },
        [&] {
          ++second;
          secondOn = std::this_thread::get_id();
        });
    EXPECT_EQ(first.load(), 1) << threads;
    EXPECT_EQ(second.load(), 1) << threads;
    // One worker: both in the calling thread, first then second; more: the second on another.
    EXPECT_EQ(firstOn, std::this_thread::get_id()) << threads;
    EXPECT_EQ(secondOn == std::this_thread::get_id(), std::string(threads) == "1") << threads;
  }
  const Threads t("2");
  std::atomic<bool> firstDone{false};
  EXPECT_THROW(kerf::geometry::parallelInvoke([&] { firstDone = true; }, [] { throw std::runtime_error("second"); }),
               std::runtime_error);
  EXPECT_TRUE(firstDone.load());
}

TEST(Parallel, BesideWhenIdleRunsEveryPieceOnceAndTheCallerTakesTheRestAfterMain) {
  for (const char* threads : {"1", "2", "4"}) {
    const Threads t(threads);
    const kerf::geometry::ParallelScope scope;
    constexpr std::size_t kPieces = 400;
    std::vector<std::atomic<int>> ran(kPieces);
    std::vector<std::atomic<int>> seen(50000);
    std::atomic<bool> mainDone{false};
    std::atomic<std::size_t> afterMainHere{0}, elsewhere{0}, elsewhereDuringMain{0};
    std::atomic<int> besideInner{0};
    const std::thread::id caller = std::this_thread::get_id();
    kerf::geometry::runBesideWhenIdle(
        [&] {
          // main's own parallelFor still has every worker and covers every index once; then a
          // serial stretch of main's, when the kept threads are free for the pieces.
          parallelFor(seen.size(), 16, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) ++seen[i];
          });
          // Until a kept thread has taken a piece (10 s at most: a loaded machine is slow, not wrong).
          const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
          while (std::string(threads) != "1" && elsewhere.load() == 0 && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          mainDone = true;
        },
        kPieces,
        [&](std::size_t k) {
          ++ran[k];
          if (std::this_thread::get_id() == caller) {
            EXPECT_TRUE(mainDone.load());  // the caller takes pieces only once main has returned
            ++afterMainHere;
          } else {
            ++elsewhere;
            if (!mainDone.load()) ++elsewhereDuringMain;
          }
          // A parallelFor inside a piece runs where the piece runs, serially.
          std::atomic<int> calls{0};
          std::thread::id on;
          parallelFor(5000, 16, [&](std::size_t, std::size_t) {
            ++calls;
            on = std::this_thread::get_id();
          });
          if (calls.load() == 1 && on == std::this_thread::get_id()) ++besideInner;
          std::this_thread::sleep_for(std::chrono::microseconds(200));
        });
    EXPECT_TRUE(std::all_of(ran.begin(), ran.end(), [](const std::atomic<int>& v) { return v.load() == 1; }))
        << threads;
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](const std::atomic<int>& v) { return v.load() == 1; }))
        << threads;
    EXPECT_EQ(afterMainHere.load() + elsewhere.load(), kPieces) << threads;
    EXPECT_EQ(besideInner.load(), static_cast<int>(kPieces)) << threads;
    if (std::string(threads) == "1") {
      EXPECT_EQ(elsewhere.load(), 0U);  // one worker: main, then every piece here
    } else {
      EXPECT_GT(elsewhereDuringMain.load(), 0U) << threads;  // the kept threads took some while main waited
      EXPECT_GT(afterMainHere.load(), 0U) << threads;        // and 80 ms of pieces outlast that wait
    }
  }
  // Outside a scope there are no kept threads: main, then every piece, here.
  {
    const Threads t("2");
    std::atomic<std::size_t> here{0};
    const std::thread::id caller = std::this_thread::get_id();
    kerf::geometry::runBesideWhenIdle([] {}, 10,
                                      [&](std::size_t) {
                                        if (std::this_thread::get_id() == caller) ++here;
                                      });
    EXPECT_EQ(here.load(), 10U);
  }
  // An exception from main or a piece reaches the caller once the pieces running have ended;
  // main's when both throw; no piece starts after one has thrown.
  const Threads t("2");
  const kerf::geometry::ParallelScope scope;
  std::atomic<int> started{0};
  EXPECT_THROW(kerf::geometry::runBesideWhenIdle([] {}, 1000,
                                                 [&](std::size_t k) {
                                                   ++started;
                                                   if (k == 3) throw std::runtime_error("piece");
                                                   // Long enough that the throw is seen long before
                                                   // the other pieces could all have started.
                                                   std::this_thread::sleep_for(std::chrono::microseconds(50));
                                                 }),
               std::runtime_error);
  EXPECT_LT(started.load(), 500);  // pieces already taken when the throw was seen, and no more
  started = 0;
  try {
    kerf::geometry::runBesideWhenIdle([] { throw std::logic_error("main"); }, 50,
                                      [&](std::size_t) {
                                        ++started;
                                        throw std::runtime_error("piece");
                                      });
    ADD_FAILURE() << "no exception";
  } catch (const std::logic_error&) {
    EXPECT_LE(started.load(), 1);
  }
}

}  // namespace

namespace {

TEST(Parallel, CallsFromInsideABodyAndManyInARowEachGiveEveryIndexOnce) {
  // A call from inside a body (on the calling thread or on another) runs its own chunks, and
  // thousands of calls in a row each give every index once.
  const Threads t("3");
  constexpr std::size_t kOuter = 6, kInner = 50;
  std::vector<std::atomic<int>> seen(kOuter * kInner);
  parallelFor(kOuter, 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t o = b; o < e; ++o)
      parallelFor(kInner, 1, [&](std::size_t ib, std::size_t ie) {
        for (std::size_t i = ib; i < ie; ++i) ++seen[o * kInner + i];
      });
  });
  for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i].load(), 1) << i;
  std::vector<std::size_t> sums(3000);
  for (std::size_t call = 0; call < sums.size(); ++call) {
    std::vector<std::size_t> part(3, 0);
    parallelFor(3, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) part[i] = call + i;
    });
    sums[call] = part[0] + part[1] + part[2];
  }
  for (std::size_t call = 0; call < sums.size(); ++call) ASSERT_EQ(sums[call], 3 * call + 3) << call;
}

}  // namespace

namespace {

TEST(Parallel, AScopeKeepsThreadsForItsCallsAndScopesNest) {
  // Inside a scope the calls run on kept threads (the same ones, call after call); calls after
  // the scope, and calls from inside a body, still give every index once.
  const Threads t("3");
  const std::thread::id caller = std::this_thread::get_id();
  auto idsOfOneCall = [&] {
    std::vector<std::thread::id> ids(3);
    parallelFor(3, 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ids[i] = std::this_thread::get_id();
    });
    return ids;
  };
  {
    const kerf::geometry::ParallelScope outer;
    const kerf::geometry::ParallelScope inner;  // nested: the outer one keeps the threads
    const auto first = idsOfOneCall();
    EXPECT_EQ(first[0], caller);
    EXPECT_NE(first[1], caller);
    EXPECT_NE(first[2], caller);
    std::size_t same = 0;
    for (int call = 0; call < 20; ++call) {
      const auto again = idsOfOneCall();
      same += again[1] == first[1] && again[2] == first[2];
    }
    EXPECT_EQ(same, 20u);  // kept, not made again
  }
  const auto after = idsOfOneCall();  // the scope's threads are gone; the call makes its own
  EXPECT_EQ(after[0], caller);
  EXPECT_NE(after[1], caller);
}

}  // namespace
