#include "kerf/converter/source.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cerrno>
#include <csignal>
#include <cstring>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kerf::converter {

namespace {

/// 64-bit hash of a text (multiply-xorshift mixes): enough to tell that a file changed, not a
/// cryptographic check. Four lanes of 8 bytes each, mixed apart and joined at the end, so the
/// multiplications overlap: about 0.3 ms for 6 MB (one lane took 1 ms).
std::uint64_t hashOf(std::string_view text) {
  const auto mix = [](std::uint64_t h, std::uint64_t w) {
    h = (h ^ w) * 0x9E3779B97F4A7C15ull;
    return h ^ (h >> 32);
  };
  std::uint64_t lane[4] = {0x243F6A8885A308D3ull ^ text.size(), 0x13198A2E03707344ull, 0xA4093822299F31D0ull,
                           0x082EFA98EC4E6C89ull};
  std::size_t k = 0;
  for (; k + 32 <= text.size(); k += 32)
    for (int l = 0; l < 4; ++l) {
      std::uint64_t w;
      std::memcpy(&w, text.data() + k + 8 * l, 8);
      lane[l] = mix(lane[l], w);
    }
  std::uint64_t h = lane[0];
  for (int l = 1; l < 4; ++l) h = mix(h, lane[l]);
  for (; k + 8 <= text.size(); k += 8) {
    std::uint64_t w;
    std::memcpy(&w, text.data() + k, 8);
    h = mix(h, w);
  }
  std::uint64_t tail = 0;
  std::memcpy(&tail, text.data() + k, text.size() - k);
  h = mix(h, tail);
  return h ^ (h >> 29);
}

// Line feeds, 16 bytes at a time where SSE2 is there (every x86-64): a byte compare gives a mask.
// Elsewhere 8 bytes at a time in a word: a word's line feeds are its zero bytes after an exclusive
// or with "\n" in every byte (the exact test: no false hits from a borrow, as the classic one has).
#if defined(__SSE2__)
/// The line feeds among data[0, size).
std::size_t countFeeds(const char* data, std::size_t size) {
  const __m128i feed = _mm_set1_epi8('\n');
  std::size_t count = 0, k = 0;
  // Each compare adds 1 (as -1 taken away) to a byte lane; the lanes are summed before they could
  // reach 256.
  while (k + 16 <= size) {
    __m128i lanes = _mm_setzero_si128();
    for (int r = 0; r < 255 && k + 16 <= size; ++r, k += 16) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + k));
      lanes = _mm_sub_epi8(lanes, _mm_cmpeq_epi8(bytes, feed));
    }
    const __m128i sums = _mm_sad_epu8(lanes, _mm_setzero_si128());
    count += static_cast<std::size_t>(_mm_cvtsi128_si32(sums)) +
             static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(sums, sums)));
  }
  for (; k < size; ++k) count += data[k] == '\n';
  return count;
}

/// Calls f(offset) for each line feed among data[0, size), in order.
template <typename F>
void forEachFeed(const char* data, std::size_t size, F&& f) {
  const __m128i feed = _mm_set1_epi8('\n');
  std::size_t k = 0;
  for (; k + 16 <= size; k += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + k));
    for (auto mask = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, feed))); mask != 0; mask &= mask - 1)
      f(k + static_cast<std::size_t>(std::countr_zero(mask)));
  }
  for (; k < size; ++k)
    if (data[k] == '\n') f(k);
}
#else
constexpr std::uint64_t kLow7 = 0x7F7F7F7F7F7F7F7FULL, kFeeds = 0x0A0A0A0A0A0A0A0AULL;
std::uint64_t feedBits(const char* at) {  // the top bit of each byte that is a line feed
  std::uint64_t w;
  std::memcpy(&w, at, 8);
  const std::uint64_t x = w ^ kFeeds;
  return ~(((x & kLow7) + kLow7) | x | kLow7);
}

std::size_t countFeeds(const char* data, std::size_t size) {
  std::size_t count = 0, k = 0;
  // The feeds of a word, one bit in the top of each byte, added up by a multiplication
  // (std::popcount is a library call on some baselines).
  for (; k + 8 <= size; k += 8)
    count += static_cast<std::size_t>(((feedBits(data + k) >> 7) * 0x0101010101010101ULL) >> 56);
  for (; k < size; ++k) count += data[k] == '\n';
  return count;
}

template <typename F>
void forEachFeed(const char* data, std::size_t size, F&& f) {
  std::size_t k = 0;
  for (; k + 8 <= size; k += 8)
    for (std::uint64_t bits = feedBits(data + k); bits != 0; bits &= bits - 1)
      f(k + static_cast<std::size_t>(std::countr_zero(bits)) / 8);
  for (; k < size; ++k)
    if (data[k] == '\n') f(k);
}
#endif

}  // namespace

#if defined(__linux__)
namespace {

// The mapped texts' file pages, for the SIGBUS handler: a file cut shorter while mapped faults
// where it no longer has pages, and the handler puts zeros there instead of the process stopping.
// Slots are claimed and cleared with atomics (the handler may run on any thread at any time).
struct MappedPages {
  std::atomic<std::uintptr_t> begin{0};
  std::atomic<std::uintptr_t> end{0};
  std::atomic<bool> cut{false};
};
constexpr std::size_t kMappedSlots = 64;
std::array<MappedPages, kMappedSlots> gMapped;
std::uintptr_t gPageSize = 4096;
struct sigaction gPreviousBus {};

void onBus(int sig, siginfo_t* info, void* context) {
  const auto at = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (MappedPages& m : gMapped) {
    const std::uintptr_t begin = m.begin.load(std::memory_order_acquire);
    const std::uintptr_t end = m.end.load(std::memory_order_acquire);
    if (begin == 0 || at < begin || at >= end) continue;
    // From the page the file no longer has to the end of its pages: anonymous zeros, read-only.
    const std::uintptr_t page = at & ~(gPageSize - 1);
    if (mmap(reinterpret_cast<void*>(page), end - page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) !=
        MAP_FAILED) {
      m.cut.store(true, std::memory_order_release);
      return;  // the read is made again, of a zero
    }
    break;
  }
  // Not a mapped text's page: what was there before.
  if ((gPreviousBus.sa_flags & SA_SIGINFO) != 0 && gPreviousBus.sa_sigaction != nullptr) {
    gPreviousBus.sa_sigaction(sig, info, context);
    return;
  }
  if ((gPreviousBus.sa_flags & SA_SIGINFO) == 0 && gPreviousBus.sa_handler != SIG_DFL &&
      gPreviousBus.sa_handler != SIG_IGN) {
    gPreviousBus.sa_handler(sig);
    return;
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

/// Installs the handler once; false where it cannot be.
bool busHandlerInstalled() {
  static const bool installed = [] {
    const long page = sysconf(_SC_PAGESIZE);
    if (page <= 0) return false;
    gPageSize = static_cast<std::uintptr_t>(page);
    struct sigaction action {};
    action.sa_sigaction = onBus;
    action.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    return sigaction(SIGBUS, &action, &gPreviousBus) == 0;
  }();
  return installed;
}

int claimSlot(std::uintptr_t begin, std::uintptr_t end) {
  for (std::size_t k = 0; k < kMappedSlots; ++k) {
    std::uintptr_t free = 0;
    if (gMapped[k].begin.compare_exchange_strong(free, begin, std::memory_order_acq_rel)) {
      gMapped[k].cut.store(false, std::memory_order_relaxed);
      gMapped[k].end.store(end, std::memory_order_release);
      return static_cast<int>(k);
    }
  }
  return -1;
}

void clearSlot(int slot) {
  gMapped[static_cast<std::size_t>(slot)].end.store(0, std::memory_order_release);
  gMapped[static_cast<std::size_t>(slot)].begin.store(0, std::memory_order_release);
}

}  // namespace
#endif

std::optional<TextBytes> TextBytes::mapFile(int fd, std::size_t size) {
#if defined(__linux__) && defined(MAP_POPULATE)
  if (size < kMapFrom || size >= SourceFile::kMaxSize || !busHandlerInstalled()) return std::nullopt;
  const std::uintptr_t page = gPageSize;
  const std::size_t whole = size / page * page;                    // the file's whole pages, mapped
  const std::size_t length = (size + 1 + page - 1) / page * page;  // then its last bytes and a NUL
  void* room = mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (room == MAP_FAILED) return std::nullopt;
  char* const at = static_cast<char*>(room);
  TextBytes t;
  t.map_ = at;
  t.mapSize_ = size;
  t.mapLength_ = length;
  // The last bytes are copied after the mapped pages, so that the NUL after them is ours: the
  // part of the file's last page past its end would show what is appended to it meanwhile.
  std::size_t got = whole;
  while (got < size) {
    const ssize_t n = pread(fd, at + got, size - got, static_cast<off_t>(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;  // shorter than it was: read it
    got += static_cast<std::size_t>(n);
  }
  char more = 0;
  ssize_t extra = 0;
  do extra = pread(fd, &more, 1, static_cast<off_t>(size));
  while (extra < 0 && errno == EINTR);
  if (extra != 0) return std::nullopt;  // longer than it was: read it
  if (whole > 0) {
    t.slot_ = claimSlot(reinterpret_cast<std::uintptr_t>(at), reinterpret_cast<std::uintptr_t>(at) + whole);
    if (t.slot_ < 0) return std::nullopt;
    if (mmap(at, whole, PROT_READ, MAP_PRIVATE | MAP_FIXED | MAP_POPULATE, fd, 0) == MAP_FAILED) return std::nullopt;
  }
  return t;
#else
  (void)fd;
  (void)size;
  return std::nullopt;
#endif
}

void TextBytes::unmap() noexcept {
#if defined(__linux__)
  if (map_ == nullptr) return;
  if (slot_ >= 0) clearSlot(slot_);
  (void)munmap(map_, mapLength_);
#endif
  map_ = nullptr;
  mapSize_ = mapLength_ = 0;
  slot_ = -1;
}

bool TextBytes::cutShort() const {
#if defined(__linux__)
  return slot_ >= 0 && gMapped[static_cast<std::size_t>(slot_)].cut.load(std::memory_order_acquire);
#else
  return false;
#endif
}

TextBytes::TextBytes(const TextBytes& other) : TextBytes(other.view()) {}

TextBytes& TextBytes::operator=(const TextBytes& other) {
  if (this != &other) *this = TextBytes(other);
  return *this;
}

TextBytes::TextBytes(TextBytes&& other) noexcept
    : bytes_(std::move(other.bytes_)),
      map_(std::exchange(other.map_, nullptr)),
      mapSize_(std::exchange(other.mapSize_, 0)),
      mapLength_(std::exchange(other.mapLength_, 0)),
      slot_(std::exchange(other.slot_, -1)) {}

TextBytes& TextBytes::operator=(TextBytes&& other) noexcept {
  if (this == &other) return *this;
  unmap();
  bytes_ = std::move(other.bytes_);
  map_ = std::exchange(other.map_, nullptr);
  mapSize_ = std::exchange(other.mapSize_, 0);
  mapLength_ = std::exchange(other.mapLength_, 0);
  slot_ = std::exchange(other.slot_, -1);
  return *this;
}

TextBytes::~TextBytes() { unmap(); }

TextBytes::TextBytes(std::string_view text) {
  bytes_.reserve(text.size() + 1);
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  bytes_.push_back('\0');
}

TextBytes TextBytes::ofSize(std::size_t n) {
  TextBytes t;
  t.bytes_.resize(n + 1);  // left for the caller (FillLaterAllocator), but for the NUL after them
  t.bytes_[n] = '\0';
  return t;
}

void TextBytes::shrink(std::size_t n) {
  if (n >= size()) return;
  if (map_) {  // a mapping keeps its NUL after the file's end: the first n bytes become bytes of its own
    *this = TextBytes(view().substr(0, n));
    return;
  }
  bytes_.resize(n + 1);
  bytes_[n] = '\0';
}

SourceFile::SourceFile(std::string name, TextBytes text)
    : name_(std::move(name)), text_(std::move(text)), size_(text_.size()) {
  lineStarts_.push_back(0);
  const char* data = text_.data();
  const std::size_t size = text_.size();
  if (std::memchr(data, '\r', size) == nullptr) {  // LF only: the fast way
    // The starts are counted first, so the list is made at its size once, then written.
    const std::size_t count = countFeeds(data, size);
    lineStarts_.resize(count + 1);
    std::uint32_t* out = lineStarts_.data() + 1;
    forEachFeed(data, size, [&](std::size_t at) { *out++ = static_cast<std::uint32_t>(at + 1); });
    return;
  }
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n' || (data[i] == '\r' && (i + 1 == size || data[i + 1] != '\n')))
      lineStarts_.push_back(static_cast<std::uint32_t>(i + 1));
  }
}

SourceLocation SourceFile::locate(std::uint32_t offset) const {
  const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(it - lineStarts_.begin());  // 1-based
  return {line, offset - lineStarts_[line - 1] + 1};
}

void SourceFile::releaseText(TextSource readAgain) {
  if (released_ || !readAgain) return;
  readAgain_ = std::move(readAgain);
  hash_ = hashOf(text_.view());
  cutShort_ = cutShort_ || text_.cutShort();
  text_ = TextBytes();
  released_ = true;
}

void SourceFile::reload() const {
  released_ = false;
  std::optional<TextBytes> again = readAgain_();
  if (!again || again->size() != size_ || hashOf(again->view()) != hash_) {
    // Changed: blank lines of the old lengths keep every position valid.
    changed_ = true;
    again = TextBytes::ofSize(size_);
    std::fill_n(again->data(), size_, ' ');
    for (std::size_t k = 1; k < lineStarts_.size(); ++k) again->data()[lineStarts_[k] - 1] = '\n';
  }
  text_ = std::move(*again);  // not a copy: the text may be as long as the file may be
}

std::pair<std::uint32_t, std::uint32_t> SourceFile::lineRange(std::uint32_t line) const {
  if (line == 0 || line > lineStarts_.size()) return {0, 0};
  if (released_) reload();
  const std::uint32_t begin = lineStarts_[line - 1];
  std::uint32_t end = line < lineStarts_.size() ? lineStarts_[line] : static_cast<std::uint32_t>(text_.size());
  // Drop the line break: LF, CR LF or CR.
  if (end > begin && text_.data()[end - 1] == '\n') --end;
  if (end > begin && text_.data()[end - 1] == '\r') --end;
  return {begin, end};
}

std::string_view SourceFile::lineText(std::uint32_t line) const {
  const auto [begin, end] = lineRange(line);
  return text().substr(begin, end - begin);
}

}  // namespace kerf::converter
