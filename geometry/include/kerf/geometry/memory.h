// Memory for the few large arrays a long program fills once (its text, the parse tree, the moves,
// the sweep's order): mappings of their own on Linux (mmap, madvise); elsewhere, under
// AddressSanitizer, or when the system declines the advice, nothing changes but the time and the
// memory it takes.
//
// Why: a page the process touches first costs a fault, and on the virtual machines Kerf is built
// and tested on a fault costs about 1.8 µs per 4 KiB page (32 MiB touched: 14-17 ms) against
// about 0.1 ms per MiB in 2 MiB pages. With transparent huge pages in mode "madvise" (Debian's
// default) only advised ranges get them, and only their whole 2 MiB pages: an array from malloc
// starts and ends anywhere, so up to 2 MiB at each end still faults page by page (a third of the
// faults of kerf check on a 6 MB program). And on those machines a huge page freed for about 2 s
// goes back to the host (free page reporting), so the next first write to one costs about 1.7 ms
// per MiB instead of 0.1: pages a long program's text, parse and arrays are done with are moved
// (mremap) into the arrays filled after them (adoptPages), not given to the system and faulted in
// again. kerf check of a 6 MB program faulted 30 huge pages, with this 17.
//
// Since 2026-11-26 the blocks are not advised huge unless KERF_HUGE_PAGES=1: which huge pages come
// back from the host cold is a draw (the first few a run takes are usually warm, the rest cold at
// 4.3-6.6 ms each), so kerf check of the 6 MB program took 38-114 ms between runs of rs274, median
// 62-64; in small pages, whose cost (about 0.33 ms per MiB) does not depend on the host, 45-72 ms,
// median 55-56 (41 rounds each way, twice; docs/interpreter.md, "Fresh pages"). The blocks keep
// their 2 MiB alignment and whole 2 MiB units, so that the pool moves the same units either way.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace kerf::geometry {

/// Gives the whole pages of [begin, end) back: what they held is gone (it reads as zeros after).
/// Inside a block from allocateLarge, with the pool on (adoptPages), the whole 2 MiB pages go:
/// those written in full are kept for adoptPages, and the parts of 2 MiB pages at the ends may
/// read as before, until a longer range gives their page back whole.
void releasePages(const void* begin, const void* end);

/// Moves whole 2 MiB pages that this process wrote and gave back (releasePages, freeLarge) onto
/// the untouched whole pages of [begin, end), which must lie in one block from allocateLarge and
/// which the caller writes in full before it reads them: their first write then costs no fault.
/// Returns how many pages it moved (0 where the pages are not Kerf's own, or KERF_PAGE_POOL=0).
/// allocateLarge does it for every new block; callers that fill a reserved block part by part
/// (the interpreter's windows, the parser's join) do it for the part they write next.
std::size_t adoptPages(void* begin, void* end);
/// Moves the whole 2 MiB pages that hold [from, from + bytes) onto those that start at to, without
/// copying a byte (mremap moves the page table entries): from and to 2 MiB-aligned, each range
/// inside a block of its own from allocateLarge. What to held there goes (its pages written in
/// full are kept for adoptPages), and [from, ...) reads as zeros after. False, nothing done, where
/// it cannot be done (not Kerf's own pages, KERF_PAGE_POOL=0, not Linux): the caller copies. The
/// parser joins the words its parts read this way.
bool movePages(void* to, void* from, std::size_t bytes);
/// How many pages are waiting to be adopted (tests; a text's line starts take one pass only when
/// none are: converter/source.cpp).
[[nodiscard]] std::size_t parkedPages();

/// From this size on LargeAllocator maps whole 2 MiB pages of its own (smaller blocks come from
/// operator new). A block is rounded up to whole 2 MiB pages: at most 2 MiB more, only in address
/// space until touched.
inline constexpr std::size_t kLargeBlock = std::size_t{1} << 20;

/// bytes from fresh 2 MiB-aligned pages (at least kLargeBlock; advised huge with
/// KERF_HUGE_PAGES=1), else operator new; throws std::bad_alloc when the system has no memory for it.
void* allocateLarge(std::size_t bytes);
/// Frees what allocateLarge(bytes) gave, with the same bytes.
void freeLarge(void* p, std::size_t bytes) noexcept;
/// Whether allocateLarge maps pages of its own here (Linux, not under AddressSanitizer).
[[nodiscard]] bool largePagesOwned() noexcept;

/// A standard allocator over allocateLarge: for the arrays that may grow to megabytes. Builds with
/// AddressSanitizer use operator new throughout, so that overruns are still seen.
template <typename T>
struct LargeAllocator {
  using value_type = T;
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "aligned as operator new aligns");
  LargeAllocator() = default;
  template <typename U>
  LargeAllocator(const LargeAllocator<U>& /*other*/) noexcept {}  // NOLINT: converting, as allocators are
  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocateLarge(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { freeLarge(p, n * sizeof(T)); }
  friend bool operator==(const LargeAllocator& /*a*/, const LargeAllocator& /*b*/) noexcept { return true; }
};

/// A LargeAllocator whose value-initialisation does nothing: vector::resize leaves the new elements
/// for their maker to write (on the cores that compute them, not the thread that resizes, and
/// without clearing pages that are written over next). Only for implicit-lifetime types (a scalar,
/// or an aggregate with a trivial destructor: its storage holds one without a constructor running,
/// C++20 [intro.object]) whose every element is assigned before it is read. Elements made from
/// values (push_back, emplace_back, copies) are constructed as usual.
template <typename T>
struct FillLaterAllocator : LargeAllocator<T> {
  template <typename U>
  struct rebind {
    using other = FillLaterAllocator<U>;
  };
  FillLaterAllocator() = default;
  template <typename U>
  FillLaterAllocator(const FillLaterAllocator<U>& /*other*/) noexcept {}  // NOLINT: converting, as allocators are
  template <typename U>
  void construct(U* /*at*/) noexcept {
    static_assert(std::is_scalar_v<U> || (std::is_aggregate_v<U> && std::is_trivially_destructible_v<U>),
                  "an implicit-lifetime type");
  }
  template <typename U, typename... Args>
  void construct(U* at, Args&&... args) {
    std::construct_at(at, std::forward<Args>(args)...);
  }
};

/// A vector whose storage comes from LargeAllocator.
template <typename T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace kerf::geometry
