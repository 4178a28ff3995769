#include "kerf/geometry/phase_times.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string_view>
#include <thread>
#include <vector>

using namespace kerf::geometry;

namespace {

std::vector<std::string_view> names(const std::vector<PhaseMark>& marks) {
  std::vector<std::string_view> out;
  for (const PhaseMark& m : marks) out.emplace_back(m.what);
  return out;
}

}  // namespace

// One process per test (gtest_discover_tests), so each starts with the recorder off and empty.
TEST(phase_times, nothing_is_recorded_until_the_program_turns_it_on) {
  markPhase("before");
  EXPECT_TRUE(phaseMarks().empty());
  enablePhaseTimes();
  markPhase("after");
  ASSERT_EQ(phaseMarks().size(), 1u);
  EXPECT_EQ(std::string_view(phaseMarks().front().what), "after");
}

TEST(phase_times, marks_keep_their_order_and_count_the_pages_touched_between) {
  enablePhaseTimes();
  markPhase("first");
  // 8 MiB touched for the first time: at least 4 faults even in 2 MiB pages, 2048 in small ones.
  constexpr std::size_t kBytes = std::size_t{8} << 20;
  std::unique_ptr<char[]> fresh(new char[kBytes]);
  for (std::size_t i = 0; i < kBytes; i += 4096) fresh[i] = static_cast<char>(i);
  markPhase("second");
  const std::vector<PhaseMark> marks = phaseMarks();
  ASSERT_EQ(names(marks), (std::vector<std::string_view>{"first", "second"}));
  EXPECT_LE(marks[0].ms, marks[1].ms);
  EXPECT_GE(marks[0].ms, 0.0);
#if defined(__unix__)
  EXPECT_GE(marks[1].minorFaults - marks[0].minorFaults, 4) << "the fresh pages were not counted";
#endif
  EXPECT_NE(fresh[4096], 1);  // keeps the writes
}

TEST(phase_times, every_thread_may_mark_and_the_table_stops_at_its_size) {
  enablePhaseTimes();
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([] {
      for (int k = 0; k < 100; ++k) markPhase("thread");
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(phaseMarks().size(), 400u);
  for (int k = 0; k < 1000; ++k) markPhase("more");
  const std::vector<PhaseMark> marks = phaseMarks();
  ASSERT_EQ(marks.size(), kMostPhaseMarks);
  for (const PhaseMark& m : marks) EXPECT_NE(m.what, nullptr);
  EXPECT_EQ(std::string_view(marks.back().what), "more");
}
