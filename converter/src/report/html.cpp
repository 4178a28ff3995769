// Building blocks of Kerf's HTML pages (html.h).
#include "kerf/converter/report/html.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace kerf::converter {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

/// The length of the UTF-8 sequence at text[i] (1 to 4), or 0 when none starts there: a stray
/// continuation byte, an overlong form, a surrogate, a code point past U+10FFFF, a cut sequence.
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) return 1;
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
    cp = b & 0x1FU;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    cp = b & 0x0FU;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    cp = b & 0x07U;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0U) != 0x80U) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3FU);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  const bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
  return overlong || surrogate || cp > 0x10FFFF ? 0 : n;
}

/// SHA-256's round constants and initial hash: the first 32 bits of the fractional parts of the cube
/// roots of the first 64 primes, and of the square roots of the first 8 (FIPS 180-4, 4.2.2 and
/// 5.3.3), computed in long double (64-bit mantissa: the 32 bits after the point are exact).
struct Sha256Constants {
  std::array<std::uint32_t, 64> k{};
  std::array<std::uint32_t, 8> h{};
  Sha256Constants() {
    std::size_t found = 0;
    for (unsigned p = 2; found < 64; ++p) {
      bool prime = true;
      for (unsigned d = 2; d * d <= p; ++d) prime = prime && p % d != 0;
      if (!prime) continue;
      const auto fraction = [](long double x) {
        return static_cast<std::uint32_t>(std::floor((x - std::floor(x)) * 4294967296.0L));
      };
      k[found] = fraction(std::cbrt(static_cast<long double>(p)));
      if (found < 8) h[found] = fraction(std::sqrt(static_cast<long double>(p)));
      ++found;
    }
  }
};

std::uint32_t rotr(std::uint32_t x, unsigned n) { return (x >> n) | (x << (32 - n)); }

}  // namespace

std::string markupText(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8Length(text, i);
    if (n == 0) {
      out += kReplacement;
      ++i;
      continue;
    }
    if (n > 1) {
      out.append(text, i, n);
      i += n;
      continue;
    }
    const char c = text[i++];
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      case '\t':
      case '\n':
      case '\r': out += c; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
          out += kReplacement;
        else
          out += c;
    }
  }
  return out;
}

std::string scriptJson(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (json.compare(i, 3, "\xE2\x80\xA8") == 0 || json.compare(i, 3, "\xE2\x80\xA9") == 0) {
      out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

std::array<std::uint8_t, 32> sha256(std::string_view bytes) {
  static const Sha256Constants c;
  std::array<std::uint32_t, 8> h = c.h;
  // The message, a 1 bit, zeros to 56 bytes mod 64, and its length in bits (big-endian).
  std::vector<std::uint8_t> m(bytes.begin(), bytes.end());
  m.push_back(0x80);
  while (m.size() % 64 != 56) m.push_back(0);
  const std::uint64_t bits = static_cast<std::uint64_t>(bytes.size()) * 8;
  for (int s = 56; s >= 0; s -= 8) m.push_back(static_cast<std::uint8_t>(bits >> s));
  std::array<std::uint32_t, 64> w{};
  for (std::size_t block = 0; block < m.size(); block += 64) {
    for (std::size_t t = 0; t < 16; ++t)
      w[t] = std::uint32_t{m[block + 4 * t]} << 24 | std::uint32_t{m[block + 4 * t + 1]} << 16 |
             std::uint32_t{m[block + 4 * t + 2]} << 8 | std::uint32_t{m[block + 4 * t + 3]};
    for (std::size_t t = 16; t < 64; ++t) {
      const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
      const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
      w[t] = w[t - 16] + s0 + w[t - 7] + s1;
    }
    std::array<std::uint32_t, 8> v = h;  // a b c d e f g h
    for (std::size_t t = 0; t < 64; ++t) {
      const std::uint32_t s1 = rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25);
      const std::uint32_t ch = (v[4] & v[5]) ^ (~v[4] & v[6]);
      const std::uint32_t t1 = v[7] + s1 + ch + c.k[t] + w[t];
      const std::uint32_t s0 = rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22);
      const std::uint32_t maj = (v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]);
      for (std::size_t k = 7; k > 0; --k) v[k] = v[k - 1];
      v[4] += t1;
      v[0] = t1 + s0 + maj;
    }
    for (std::size_t k = 0; k < 8; ++k) h[k] += v[k];
  }
  std::array<std::uint8_t, 32> digest{};
  for (std::size_t k = 0; k < 32; ++k) digest[k] = static_cast<std::uint8_t>(h[k / 4] >> (24 - 8 * (k % 4)));
  return digest;
}

std::string base64(std::span<const std::uint8_t> bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t triple = std::uint32_t{bytes[i]} << 16;
    if (n > 1) triple |= std::uint32_t{bytes[i + 1]} << 8;
    if (n > 2) triple |= bytes[i + 2];
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(triple >> (18 - 6 * k)) & 0x3F] : '=';
  }
  return out;
}

std::string programTitle(std::string_view name, std::string_view suffix) {
  constexpr std::size_t kLongest = 48;
  const std::size_t slash = name.find_last_of('/');
  std::string_view base = slash == std::string_view::npos ? name : name.substr(slash + 1);
  std::string title(base);
  if (title.size() > kLongest) {
    std::size_t cut = kLongest;
    while (cut > 0 && (static_cast<unsigned char>(title[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
    title = title.substr(0, cut) + "…";
  }
  return title + std::string(suffix);
}

std::string contentSecurityPolicy(std::span<const std::string_view> scripts, std::span<const std::string_view> styles,
                                  bool scriptFiles) {
  auto hashes = [](std::span<const std::string_view> texts) {
    std::string out;
    for (const std::string_view t : texts) out += " 'sha256-" + base64(sha256(t)) + "'";
    return texts.empty() ? std::string(" 'none'") : out;
  };
  const std::string scriptSources = scriptFiles ? std::string(" 'self'") : hashes(scripts);
  return "default-src 'none'; script-src" + scriptSources + "; style-src" + hashes(styles) +
         "; img-src 'self' data:; base-uri 'none'; form-action 'none'";
}

}  // namespace kerf::converter
