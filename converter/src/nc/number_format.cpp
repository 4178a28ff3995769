#include "kerf/converter/nc/number_format.h"

#include <charconv>

namespace kerf::converter {

std::string formatFixed(double v, int decimals) {
  // Room for any finite double in fixed notation (309 digits before the point) with its decimals.
  char buf[400];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) return "nan";  // only past 60 decimals
  std::string s(buf, r.ptr);
  // "-0.000" (a negative number that rounds to zero) is written as "0.000".
  if (!s.empty() && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string formatPoint(const geometry::Vec2& p, int decimals) {
  return "(" + formatFixed(p.x(), decimals) + ", " + formatFixed(p.y(), decimals) + ")";
}

}  // namespace kerf::converter
