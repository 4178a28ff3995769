#include "kerf/geometry/memory.h"

#include <cstdint>

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

}  // namespace

void releasePages(const void* begin, const void* end) {
#if defined(__linux__)
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

void* allocateLarge(std::size_t bytes) {
  if (!ownPages(bytes)) return ::operator new(bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Mapped 2 MiB too long, then trimmed at both ends to whole aligned 2 MiB pages.
  const std::size_t size = wholeHugePages(bytes);
  if (size < bytes || size + kHuge < size) throw std::bad_alloc();
  void* map = mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (map == MAP_FAILED) throw std::bad_alloc();
  const auto at = reinterpret_cast<std::uintptr_t>(map);
  const std::uintptr_t from = (at + kHuge - 1) & ~(kHuge - 1);
  if (from > at) (void)munmap(map, from - at);
  if (const std::uintptr_t tail = at + size + kHuge - (from + size); tail > 0)
    (void)munmap(reinterpret_cast<void*>(from + size), tail);
  (void)madvise(reinterpret_cast<void*>(from), size, MADV_HUGEPAGE);
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
  (void)munmap(p, wholeHugePages(bytes));
#endif
}

}  // namespace kerf::geometry
