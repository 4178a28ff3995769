// Toolpath::replaceMoves: every table indexed by move stays aligned with the moves, and every list
// that names moves follows them, when moves are removed and inserted (toolpath.h). A table added
// to MoveTables without its MoveRow field fails the build (toolpath.cpp's static_assert); one
// given a field but not filled here fails `every_table_follows_its_move`.
#include "kerf/converter/toolpath.h"

#include <gtest/gtest.h>

namespace {

using namespace kerf::converter;  // NOLINT: the test names Toolpath's parts throughout
using kerf::geometry::Segment;
using kerf::geometry::Vec2;

/// Four moves along x, each table's entry for move i made from i so that a misaligned entry shows.
Toolpath fourMoves() {
  Toolpath tp;
  for (int i = 0; i < 4; ++i) {
    Move m;
    m.lower = Segment::line(Vec2(i, 0), Vec2(i + 1, 0));
    m.line = static_cast<std::uint32_t>(i + 1);
    tp.moves.push_back(m);
    tp.upper.push_back(Segment::line(Vec2(i, 1), Vec2(i + 1, 1)));
    tp.programmed.push_back(Segment::line(Vec2(i, 2), Vec2(i + 1, 2)));
    tp.offsetRole.push_back(i % 2 == 0 ? OffsetRole::Element : OffsetRole::Corner);
    tp.taperDegrees.push_back(static_cast<float>(i) + 0.5F);
    tp.centreWords.push_back(Vec2(i, -i));
    tp.setFeedFrom(i, 100.0 * (i % 2 == 0 ? 1 : 2));  // 100, 200, 100, 200 mm/min
  }
  tp.stops = {1, 3};
  tp.conditions = {{0, "C001"}, {2, "C002"}};
  tp.corners = {{1, 0.5, false, Vec2(2, 0)}, {3, 0.2, true, Vec2(4, 0)}};
  OffsetSpan span;
  span.first = 2;
  span.end = 4;
  tp.offsetSpans = {span};
  return tp;
}

void expectSameRow(const MoveRow& a, const MoveRow& b) {
  EXPECT_EQ(a.move.line, b.move.line);
  EXPECT_EQ(a.move.lower.start, b.move.lower.start);
  EXPECT_EQ(a.upper.start, b.upper.start);
  EXPECT_EQ(a.programmed.start, b.programmed.start);
  EXPECT_EQ(a.offsetRole, b.offsetRole);
  EXPECT_EQ(a.taperDegrees, b.taperDegrees);
  EXPECT_EQ(a.centreWords, b.centreWords);
  EXPECT_EQ(a.feed, b.feed);
}

// Old move 1 removed, a new move inserted before old move 3: new order 0, 2, new, 3.
TEST(toolpath_test, every_table_follows_its_move) {
  const Toolpath old = fourMoves();
  Toolpath tp = old;
  MoveRow inserted = old.rowOf(3);
  inserted.move.line = 99;
  inserted.taperDegrees = 9.0F;
  inserted.feed = 0.0;  // no feed programmed
  std::vector<MoveRow> rows = {old.rowOf(0), old.rowOf(2), inserted, old.rowOf(3)};
  tp.replaceMoves(std::move(rows), {0, 1, 1, 3, 4});
  ASSERT_EQ(tp.moves.size(), 4U);
  for (const std::size_t size :
       {tp.upper.size(), tp.programmed.size(), tp.offsetRole.size(), tp.taperDegrees.size(), tp.centreWords.size()})
    EXPECT_EQ(size, tp.moves.size());
  expectSameRow(tp.rowOf(0), old.rowOf(0));
  expectSameRow(tp.rowOf(1), old.rowOf(2));
  EXPECT_EQ(tp.rowOf(2).move.line, 99U);
  EXPECT_EQ(tp.rowOf(2).taperDegrees, 9.0F);
  EXPECT_EQ(tp.feedOf(2), 0.0);
  expectSameRow(tp.rowOf(3), old.rowOf(3));
  // The lists that name moves: stop 1 (old move 1, removed) lands on old move 2's place.
  EXPECT_EQ(tp.stops, (std::vector<std::uint32_t>{1, 3}));
  EXPECT_EQ(tp.conditions[1].from, 1U);
  ASSERT_EQ(tp.corners.size(), 1U);  // the corner made as old move 1 went with it
  EXPECT_EQ(tp.corners[0].move, 3U);
  ASSERT_EQ(tp.offsetSpans.size(), 1U);
  EXPECT_EQ(tp.offsetSpans[0].first, 1U);
  EXPECT_EQ(tp.offsetSpans[0].end, 4U);
}

// The feeds are kept as changes: one where the feed changes, none where it stays; a change at a
// move that has not run yet replaces the one before it.
TEST(toolpath_test, feeds_are_kept_where_they_change) {
  Toolpath tp;
  EXPECT_EQ(tp.feedOf(0), 0.0);
  tp.setFeedFrom(0, 0.0);  // none: no change
  EXPECT_TRUE(tp.feedChanges.empty());
  tp.setFeedFrom(2, 150.0);
  tp.setFeedFrom(3, 150.0);
  tp.setFeedFrom(5, 90.0);
  tp.setFeedFrom(5, 80.0);  // replaces 90 before move 5 ran
  tp.setFeedFrom(7, -1.0);  // a value <= 0 is none
  ASSERT_EQ(tp.feedChanges.size(), 3U);
  for (const auto& [move, feed] :
       {std::pair{0, 0.0}, {1, 0.0}, {2, 150.0}, {4, 150.0}, {5, 80.0}, {6, 80.0}, {7, 0.0}, {100, 0.0}})
    EXPECT_EQ(tp.feedOf(move), feed) << move;
  tp.setFeedFrom(7, 80.0);  // back to the feed before: the change at 7 goes
  ASSERT_EQ(tp.feedChanges.size(), 2U);
  EXPECT_EQ(tp.feedOf(9), 80.0);
}

// A table the program does not keep stays empty; the offset tables start when the offset applies.
TEST(toolpath_test, tables_not_kept_stay_empty_until_the_offset_applies) {
  Toolpath plain;
  Move m;
  m.lower = Segment::line(Vec2(0, 0), Vec2(1, 0));
  plain.moves = {m, m};
  std::vector<MoveRow> rows = {plain.rowOf(0), plain.rowOf(1)};
  EXPECT_EQ(rows[0].upper.end, m.lower.end);  // a plain move's upper is its lower
  Toolpath copy = plain;
  copy.replaceMoves(std::vector<MoveRow>(rows), {0, 1, 2});
  EXPECT_TRUE(copy.upper.empty());
  EXPECT_TRUE(copy.offsetRole.empty());
  EXPECT_TRUE(copy.centreWords.empty());
  rows[1].offsetRole = OffsetRole::Cancel;
  plain.replaceMoves(std::move(rows), {0, 1, 2}, true);
  ASSERT_EQ(plain.offsetRole.size(), 2U);
  ASSERT_EQ(plain.programmed.size(), 2U);
  EXPECT_EQ(plain.offsetRole[1], OffsetRole::Cancel);
  EXPECT_TRUE(plain.upper.empty());
}

}  // namespace
