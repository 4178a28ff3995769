// Memory advice for the few large arrays a long program fills once (its text, the parse tree, the
// moves): Linux madvise, advice only — on other systems, or when the system declines, nothing
// changes but the time and the memory it takes.
#pragma once

#include <cstddef>
#include <vector>

namespace kerf::converter {

/// Asks the system to back the whole 2 MiB pages inside [begin, begin + bytes) with huge pages,
/// where it does so only on request (transparent huge pages in mode "madvise", Debian's default):
/// an array filled once then faults once every 2 MiB instead of every 4 KiB. Below 4 MiB nothing
/// is asked.
void adviseHugePages(const void* begin, std::size_t bytes);

/// Gives the whole pages of [begin, end) back to the system; what they held reads as zeros after.
void releasePages(const void* begin, const void* end);

/// Reserves n elements in v and advises huge pages for them (adviseHugePages).
template <typename T, typename A>
void reserveLarge(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace kerf::converter
