// Toolpath: the tables indexed by move kept aligned, and the lists that name moves renumbered,
// through one operation (toolpath.h).
#include "kerf/converter/toolpath.h"

#include <algorithm>
#include <iterator>
#include <tuple>

namespace kerf::converter {
namespace {

/// Every table of MoveTables but `moves`, with its MoveRow field: the one list rowOf and
/// replaceMoves walk.
constexpr auto kRowTables = std::make_tuple(std::pair{&MoveTables::upper, &MoveRow::upper},
                                            std::pair{&MoveTables::programmed, &MoveRow::programmed},
                                            std::pair{&MoveTables::offsetRole, &MoveRow::offsetRole},
                                            std::pair{&MoveTables::taperDegrees, &MoveRow::taperDegrees},
                                            std::pair{&MoveTables::centreWords, &MoveRow::centreWords});

// Every member of MoveTables is a vector; one more than kRowTables lists is a table replaceMoves
// would leave misaligned: give it its MoveRow field and its entry above.
static_assert(sizeof(MoveTables) == (std::tuple_size_v<decltype(kRowTables)> + 1) * sizeof(std::vector<char>),
              "a table indexed by move must be listed in kRowTables");

template <class F>
void forEachRowTable(F&& f) {
  std::apply([&](const auto&... table) { (f(table.first, table.second), ...); }, kRowTables);
}

}  // namespace

MoveRow Toolpath::rowOf(std::size_t i) const {
  MoveRow row{moves[i], moves[i].lower, moves[i].lower};
  forEachRowTable([&](auto table, auto field) {
    if (i < (this->*table).size()) row.*field = (this->*table)[i];
  });
  row.feed = feedOf(i);
  return row;
}

void Toolpath::replaceMoves(std::vector<MoveRow>&& rows, const std::vector<std::uint32_t>& newIndex,
                            bool offsetApplied) {
  if (offsetApplied && offsetRole.empty()) {  // kept from now on: made non-empty, filled below
    offsetRole.resize(1);
    programmed.resize(1);
  }
  forEachRowTable([&](auto table, auto field) {
    auto& t = this->*table;
    if (t.empty()) return;
    t.clear();
    t.reserve(rows.size());
    for (const MoveRow& r : rows) t.push_back(r.*field);
  });
  moves.clear();
  moves.reserve(rows.size());
  feedChanges.clear();
  for (MoveRow& r : rows) {
    setFeedFrom(moves.size(), r.feed);
    moves.push_back(r.move);
  }
  renumberMoveLists(newIndex);
}

void Toolpath::changeFeedFrom(std::size_t from, double feed) {
  if (!feedChanges.empty() && feedChanges.back().from == from) {  // no move ran at the feed it replaces
    feedChanges.pop_back();
    setFeedFrom(from, feed);  // a change from the feed before it, or none
    return;
  }
  feedChanges.push_back({static_cast<std::uint32_t>(from), feed});
}

double Toolpath::feedOf(std::size_t i) const {
  const auto after = std::upper_bound(feedChanges.begin(), feedChanges.end(), i,
                                      [](std::size_t m, const FeedChange& c) { return m < c.from; });
  return after == feedChanges.begin() ? 0.0 : std::prev(after)->mmPerMinute;
}

void Toolpath::renumberMoveLists(const std::vector<std::uint32_t>& newIndex) {
  if (newIndex.empty()) return;
  const std::size_t oldCount = newIndex.size() - 1;
  auto renumber = [&](std::uint32_t i) { return newIndex[std::min<std::size_t>(i, oldCount)]; };
  std::vector<std::uint32_t> keptStops;
  keptStops.reserve(stops.size());
  for (const std::uint32_t s : stops) {
    const std::uint32_t n = renumber(s);
    if (keptStops.empty() || keptStops.back() != n) keptStops.push_back(n);
  }
  stops = std::move(keptStops);
  for (ConditionChange& c : conditions) c.from = renumber(c.from);
  std::vector<CornerMade> keptCorners;  // a corner whose move is gone (another pass's) goes with it
  for (CornerMade& c : corners)
    if (c.move < oldCount && newIndex[c.move + 1] > newIndex[c.move]) {
      c.move = newIndex[c.move];
      keptCorners.push_back(c);
    }
  corners = std::move(keptCorners);
  std::vector<OffsetSpan> keptSpans;
  keptSpans.reserve(offsetSpans.size());
  for (OffsetSpan& s : offsetSpans) {
    const bool hadMoves = s.end > s.first;
    s.first = renumber(s.first);
    s.end = renumber(s.end);
    if (s.end > s.first || !hadMoves) keptSpans.push_back(std::move(s));
  }
  offsetSpans = std::move(keptSpans);
}

const Toolpath::CornerMade* Toolpath::cornerAt(std::size_t i) const {
  const auto it = std::lower_bound(corners.begin(), corners.end(), i,
                                   [](const CornerMade& c, std::size_t m) { return c.move < m; });
  return it != corners.end() && it->move == i ? &*it : nullptr;
}

}  // namespace kerf::converter
