#include "kerf/converter/source.h"

#include "kerf/geometry/memory.h"
#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kerf::converter {

namespace {

/// From this size on a text's line starts are found in one pass (SourceFile::SourceFile).
constexpr std::size_t kOnePassBytes = std::size_t{1} << 20;

std::uint64_t mix(std::uint64_t h, std::uint64_t w) {
  h = (h ^ w) * 0x9E3779B97F4A7C15ull;
  return h ^ (h >> 32);
}

/// 64-bit hash of a piece of text (multiply-xorshift mixes), seeded. Four lanes of 8 bytes each,
/// mixed apart and joined at the end, so the multiplications overlap: about 0.3 ms for 6 MB on
/// one core (one lane took 1 ms).
std::uint64_t hashPiece(std::string_view text, std::uint64_t seed) {
  std::uint64_t lane[4] = {0x243F6A8885A308D3ull ^ seed, 0x13198A2E03707344ull, 0xA4093822299F31D0ull,
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
  return mix(h, tail);
}

/// A text's hash: enough to tell that a file changed, not a cryptographic check. Pieces of 1 MiB
/// hashed on every core (the text is given back on the main thread while the other cores wait for
/// the interpreter), then their hashes mixed in order: the same value on any number of cores.
std::uint64_t hashOf(std::string_view text) {
  constexpr std::size_t kPiece = std::size_t{1} << 20;
  const std::size_t pieces = std::max<std::size_t>(1, (text.size() + kPiece - 1) / kPiece);
  std::vector<std::uint64_t> hashes(pieces);
  geometry::parallelFor(pieces, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) hashes[k] = hashPiece(text.substr(k * kPiece, kPiece), k);
  });
  std::uint64_t h = 0x243F6A8885A308D3ull ^ text.size();
  for (const std::uint64_t piece : hashes) h = mix(h, piece);
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

TextBytes::TextBytes(std::string_view text) {
  bytes_.reserve(text.size() + 1);
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  bytes_.push_back('\0');
}

TextBytes::TextBytes(TextBytes&& other) noexcept
    : bytes_(std::move(other.bytes_)), kept_(other.kept_), keeper_(std::move(other.keeper_)) {
  other = TextBytes();
}

TextBytes& TextBytes::operator=(const TextBytes& other) {
  if (this != &other) *this = TextBytes(other.view());
  return *this;
}

TextBytes& TextBytes::operator=(TextBytes&& other) noexcept {
  if (this == &other) return *this;
  bytes_ = std::move(other.bytes_);
  kept_ = other.kept_;
  keeper_ = std::move(other.keeper_);
  // What was moved from is empty text again (a vector moved from holds nothing, not even the NUL).
  other.bytes_.assign(1, '\0');
  other.kept_ = {};
  return *this;
}

TextBytes TextBytes::kept(const char* at, std::size_t n, std::unique_ptr<TextKeeper> keeper) {
  TextBytes t;
  if (!keeper) return TextBytes(std::string_view(at, n));
  t.kept_ = std::string_view(at, n);
  t.keeper_ = std::move(keeper);
  return t;
}

TextBytes TextBytes::ofSize(std::size_t n) {
  TextBytes t;
  t.bytes_.resize(n + 1);  // left for the caller (FillLaterAllocator), but for the NUL after them
  t.bytes_[n] = '\0';
  return t;
}

void TextBytes::shrink(std::size_t n) {
  if (n >= size()) return;
  if (keeper_) {  // kept bytes are read only: the first n are copied
    *this = TextBytes(kept_.substr(0, n));
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
    if (size >= kOnePassBytes && geometry::largePagesOwned() && geometry::parkedPages() == 0) {
      // One pass, into room for a feed at every byte: the list's pages are mapped for it alone
      // and become memory only where written (4 bytes a line), the rest is address space. The
      // pass that counted the feeds first read a long text twice (0.5 of the 1.7 ms the starts of
      // a 6 MB program took). Kept bytes that change meanwhile still hold at most size feeds.
      // Not while pages an earlier program gave back wait to be taken (a folder's next file):
      // a new block takes them all, and this one would keep them from the parse and the moves.
      lineStarts_.resize(size + 1);  // FillLaterAllocator: nothing written here
      std::uint32_t* out = lineStarts_.data() + 1;
      forEachFeed(data, size, [&](std::size_t at) { *out++ = static_cast<std::uint32_t>(at + 1); });
      lineStarts_.resize(static_cast<std::size_t>(out - lineStarts_.data()));
      return;
    }
    // The starts are counted first, so the list is made at its size once, then written.
    // Kept bytes (a mapped file) can change between the two passes when the file is written
    // meanwhile: the second never writes past what the first counted.
    const std::size_t count = countFeeds(data, size);
    lineStarts_.resize(count + 1);
    std::uint32_t* out = lineStarts_.data() + 1;
    std::uint32_t* const last = lineStarts_.data() + lineStarts_.size();
    forEachFeed(data, size, [&](std::size_t at) {
      if (out != last) *out++ = static_cast<std::uint32_t>(at + 1);
    });
    while (out != last) *out++ = static_cast<std::uint32_t>(size);  // feeds gone meanwhile: empty lines at the end
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
    std::fill_n(again->writable(), size_, ' ');
    for (std::size_t k = 1; k < lineStarts_.size(); ++k) again->writable()[lineStarts_[k] - 1] = '\n';
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
