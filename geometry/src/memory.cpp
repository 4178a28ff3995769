#include "kerf/geometry/memory.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace kerf::geometry {
namespace {

constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;

// AddressSanitizer sees overruns only in what operator new gives. GCC says it is on with
// __SANITIZE_ADDRESS__, Clang (14) only through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define KERF_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define KERF_ADDRESS_SANITIZER 1
#endif
#endif

#if defined(KERF_ADDRESS_SANITIZER)
constexpr bool kOwnPages = false;
#elif defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr bool kOwnPages = true;
#else
constexpr bool kOwnPages = false;
#endif

bool ownPages(std::size_t bytes) { return kOwnPages && bytes >= kLargeBlock; }

std::size_t wholeHugePages(std::size_t bytes) { return (bytes + kHuge - 1) & ~(kHuge - 1); }

#if defined(__linux__) && !defined(KERF_ADDRESS_SANITIZER) && defined(MADV_HUGEPAGE) && defined(MREMAP_FIXED) && \
    defined(MREMAP_DONTUNMAP)
#define KERF_PAGE_POOL 1
#endif

#if defined(__linux__)
/// A fresh mapping of size bytes (whole 2 MiB pages) at a 2 MiB-aligned address: mapped 2 MiB too
/// long, then trimmed at both ends. 0 when the system has no room for it.
std::uintptr_t mapAligned(std::size_t size, int prot, int flags) {
  void* map = mmap(nullptr, size + kHuge, prot, flags, -1, 0);
  if (map == MAP_FAILED) return 0;
  const auto at = reinterpret_cast<std::uintptr_t>(map);
  const std::uintptr_t from = (at + kHuge - 1) & ~(kHuge - 1);
  if (from > at) (void)munmap(map, from - at);
  if (const std::uintptr_t tail = at + size + kHuge - (from + size); tail > 0)
    (void)munmap(reinterpret_cast<void*>(from + size), tail);
  return from;
}
#endif

#if defined(KERF_PAGE_POOL)
/// Whole 2 MiB pages this process wrote and no longer needs (freeLarge, releasePages), moved to
/// addresses of their own (mremap moves the page table entries, not the bytes) and moved again
/// into the next large block in place of pages not yet touched.
///
/// Why: a page touched for the first time is not only zeroed. On the virtual machines Kerf is
/// built and tested on (a balloon that reports free memory to the host, CONFIG_PAGE_REPORTING),
/// free 2 MiB blocks are handed back to the host about 2 s after they are freed, and the first
/// write to such a block faults on the host as well: 40 MiB in huge pages took 3.5-4 ms when
/// the blocks were still backed and 64-88 ms after a pause of 3 s (about 1.7 ms per MiB; small
/// pages 0.4 ms per MiB either way). kerf check of a 6 MB program touched 30 huge pages, while the
/// text, the parse and the moves are each done with before the next array fills.
class PagePool {
 public:
  /// The pool, or null where it is off (KERF_PAGE_POOL=0, or a page size it cannot use).
  static PagePool* get() {
    static PagePool pool;
    return pool.enabled_ ? &pool : nullptr;
  }

  void addRegion(std::uintptr_t from, std::uintptr_t to) {
    const std::lock_guard<std::mutex> lock(mutex_);
    regions_[from] = to;
  }

  /// Parks the fully written whole pages of the region that starts at from, then forgets it.
  void removeRegion(std::uintptr_t from, std::uintptr_t to) {
    const std::lock_guard<std::mutex> lock(mutex_);
    regions_.erase(from);
    for (std::uintptr_t p = from; p + kHuge <= to; p += kHuge) (void)park(p);
  }

  /// Gives back [from, to) when it lies in one region (else false, nothing done): its whole pages
  /// written in full are parked, fresh pages that read as zeros left in their place; its other
  /// whole pages are given to the system. The parts of 2 MiB pages at its ends stay as they are:
  /// giving them to the system would split a page that a later, longer range parks whole (the
  /// callers give back ranges that grow from one start).
  bool give(std::uintptr_t from, std::uintptr_t to) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (to <= from || !inRegion(from, to)) return false;
    from = (from + kHuge - 1) & ~(kHuge - 1);
    to &= ~(kHuge - 1);
    for (std::uintptr_t p = from; p < to; p += kHuge)
      if (!park(p)) (void)madvise(reinterpret_cast<void*>(p), kHuge, MADV_DONTNEED);
    return true;
  }

  /// Moves parked pages onto the untouched whole pages of [from, to) (inside one region): the
  /// caller writes the range before it reads it. Returns how many pages it moved.
  std::size_t take(std::uintptr_t from, std::uintptr_t to) {
    const std::lock_guard<std::mutex> lock(mutex_);
    from = (from + kHuge - 1) & ~(kHuge - 1);
    to &= ~(kHuge - 1);
    if (to <= from || parked_.empty() || !inRegion(from, to)) return 0;
    std::size_t moved = 0;
    for (std::uintptr_t p = from; p < to && !parked_.empty(); p += kHuge) {
      if (residentPages(p) != 0) continue;  // already written, or being: left as it is
      const std::uintptr_t slot = parked_.back();
      if (mremap(reinterpret_cast<void*>(slot), kHuge, kHuge, MREMAP_MAYMOVE | MREMAP_FIXED,
                 reinterpret_cast<void*>(p)) == MAP_FAILED)
        break;
      parked_.pop_back();
      ++moved;
    }
    return moved;
  }

  /// Moves the whole pages of [from, from + size) onto [to, to + size) (see movePages).
  bool move(std::uintptr_t to, std::uintptr_t from, std::size_t size) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (size == 0 || to % kHuge != 0 || from % kHuge != 0 || size % kHuge != 0 || !inRegion(to, to + size) ||
        !inRegion(from, from + size) || (to < from + size && from < to + size))
      return false;
    // Pages already at to (adopted when the block was made) are kept, not dropped by the move.
    for (std::uintptr_t p = to; p < to + size; p += kHuge)
      if (residentPages(p) != 0 && !park(p)) (void)madvise(reinterpret_cast<void*>(p), kHuge, MADV_DONTNEED);
    return mremap(reinterpret_cast<void*>(from), size, size, MREMAP_MAYMOVE | MREMAP_FIXED | MREMAP_DONTUNMAP,
                  reinterpret_cast<void*>(to)) != MAP_FAILED;
  }

  [[nodiscard]] std::size_t parked() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return parked_.size();
  }

 private:
  /// At most this many pages parked (32 MiB): what is parked counts in the process's memory, and
  /// arrays from malloc do not take it (a program's windows give back and take about 5 pages at
  /// a time).
  static constexpr std::size_t kMostParked = 16;

  // Nothing the pool does after this allocates: freeLarge, which parks, is noexcept.
  static constexpr std::size_t kMostSmallPages = 512;

  PagePool() {
    const char* env = std::getenv("KERF_PAGE_POOL");
    const long page = sysconf(_SC_PAGESIZE);
    page_ = page > 0 ? static_cast<std::uintptr_t>(page) : 0;
    enabled_ =
        !(env && std::strcmp(env, "0") == 0) && page_ > 0 && kHuge % page_ == 0 && kHuge / page_ <= kMostSmallPages;
    parked_.reserve(kMostParked);
  }

  bool inRegion(std::uintptr_t from, std::uintptr_t to) const {
    auto it = regions_.upper_bound(from);
    if (it == regions_.begin()) return false;
    --it;
    return it->first <= from && to <= it->second;
  }

  /// How many small pages of the huge page at p are in memory.
  std::size_t residentPages(std::uintptr_t p) {
    const std::size_t small = kHuge / page_;
    if (mincore(reinterpret_cast<void*>(p), kHuge, state_.data()) != 0) return small;
    std::size_t n = 0;
    for (std::size_t k = 0; k < small; ++k) n += state_[k] & 1u;
    return n;
  }

  /// Moves the page at p to a slot of its own, leaving p mapped as fresh memory that reads as
  /// zeros (MREMAP_DONTUNMAP, Linux 5.7): the block it was in never has a hole, whether it is still
  /// in use or about to be freed. False, nothing changed, where that cannot be done.
  /// A page at least a quarter written is parked: in small pages (memory.h) a 2 MiB unit is often
  /// written only in part where a text or an array ends, and what it holds is in memory all the same.
  bool park(std::uintptr_t p) {
    if (parked_.size() >= kMostParked || residentPages(p) * 4 < kHuge / page_) return false;
    const std::uintptr_t slot = mapAligned(kHuge, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE);
    if (slot == 0) return false;
    if (mremap(reinterpret_cast<void*>(p), kHuge, kHuge, MREMAP_MAYMOVE | MREMAP_FIXED | MREMAP_DONTUNMAP,
               reinterpret_cast<void*>(slot)) == MAP_FAILED) {
      (void)munmap(reinterpret_cast<void*>(slot), kHuge);
      return false;
    }
    parked_.push_back(slot);
    return true;
  }

  bool enabled_ = false;
  std::uintptr_t page_ = 4096;
  std::mutex mutex_;                                    // what follows
  std::map<std::uintptr_t, std::uintptr_t> regions_;    // the blocks allocateLarge mapped: start -> end
  std::vector<std::uintptr_t> parked_;                  // addresses of parked pages (reserved whole)
  std::array<unsigned char, kMostSmallPages> state_{};  // mincore's answer
};
#endif

}  // namespace

void releasePages(const void* begin, const void* end) {
#if defined(__linux__)
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get();
      pool && pool->give(reinterpret_cast<std::uintptr_t>(begin), reinterpret_cast<std::uintptr_t>(end)))
    return;
#endif
  static const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
  const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) / page * page;
  if (to > from) (void)madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
  (void)begin;
  (void)end;
#endif
}

bool largePagesOwned() noexcept { return kOwnPages; }

std::size_t adoptPages(void* begin, void* end) {
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get())
    return pool->take(reinterpret_cast<std::uintptr_t>(begin), reinterpret_cast<std::uintptr_t>(end));
#endif
  (void)begin;
  (void)end;
  return 0;
}

bool movePages(void* to, void* from, std::size_t bytes) {
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get())
    return pool->move(reinterpret_cast<std::uintptr_t>(to), reinterpret_cast<std::uintptr_t>(from),
                      wholeHugePages(bytes));
#endif
  (void)to;
  (void)from;
  (void)bytes;
  return false;
}

std::size_t parkedPages() {
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get()) return pool->parked();
#endif
  return 0;
}

void* allocateLarge(std::size_t bytes) {
  if (!ownPages(bytes)) return ::operator new(bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::size_t size = wholeHugePages(bytes);
  if (size < bytes || size + kHuge < size) throw std::bad_alloc();
  const std::uintptr_t from = mapAligned(size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS);
  if (from == 0) throw std::bad_alloc();
  // Huge pages only when asked for (memory.h: a cold one costs as much as 13 MiB of small ones).
  static const bool huge = [] {
    const char* env = std::getenv("KERF_HUGE_PAGES");
    return env && std::strcmp(env, "1") == 0;
  }();
  if (huge) (void)madvise(reinterpret_cast<void*>(from), size, MADV_HUGEPAGE);
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get()) {
    try {
      pool->addRegion(from, from + size);
    } catch (...) {  // no memory for the region's entry: the block goes back, the caller is told
      (void)munmap(reinterpret_cast<void*>(from), size);
      throw;
    }
    (void)pool->take(from, from + size);
  }
#endif
  return reinterpret_cast<void*>(from);
#else
  return ::operator new(bytes);
#endif
}

void freeLarge(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
  if (!ownPages(bytes)) {
    ::operator delete(p);
    return;
  }
#if defined(__linux__)
#if defined(KERF_PAGE_POOL)
  if (PagePool* pool = PagePool::get()) {
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    pool->removeRegion(at, at + wholeHugePages(bytes));
  }
#endif
  (void)munmap(p, wholeHugePages(bytes));
#endif
}

}  // namespace kerf::geometry
