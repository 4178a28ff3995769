// Toolpath: the lists that name moves by number, kept with the moves (toolpath.h).
#include "kerf/converter/toolpath.h"

#include <algorithm>

namespace kerf::converter {

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
