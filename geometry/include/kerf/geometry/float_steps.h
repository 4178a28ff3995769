// Doubles rounded to floats in a chosen direction, and one float step, without branches: the
// boxes the self-intersection sweeps keep (floats, rounded outwards) are made with these.
#pragma once

#include <bit>
#include <cstdint>

namespace kerf::geometry {

/// f itself when step is 0; when it is 1, the float next to f towards minus infinity, as
/// std::nextafter(f, -infinity) gives it (+infinity gives the largest finite float; f is not
/// -infinity or NaN). By the bits, since floats of one sign are ordered as their bits are: a
/// positive f steps down by one, a negative one up by one, either zero goes to the least negative
/// float. Without a branch, because which way a coordinate's rounding to a float went follows no
/// pattern, so a branch on it is mispredicted (docs/performance.md measures the difference).
inline float floatStepDownIf(float f, std::uint32_t step) {
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t stepped = bits - step + 2 * step * (bits >> 31);
  const std::uint32_t fromZero = bits + step * (0x80000001U - bits);
  const std::uint32_t zero = std::uint32_t{0} - static_cast<std::uint32_t>((bits << 1) == 0);
  return std::bit_cast<float>((stepped & ~zero) | (fromZero & zero));
}

/// f itself when step is 0; when it is 1, the float next to f towards plus infinity (f is not
/// +infinity or NaN).
inline float floatStepUpIf(float f, std::uint32_t step) { return -floatStepDownIf(-f, step); }

/// The greatest float not above v (v not NaN): past the floats' range, the largest finite float
/// of v's sign, or minus infinity below them all.
inline float floatBelow(double v) {
  const auto f = static_cast<float>(v);
  return floatStepDownIf(f, static_cast<std::uint32_t>(static_cast<double>(f) > v));
}

/// The least float not below v (v not NaN).
inline float floatAbove(double v) {
  const auto f = static_cast<float>(v);
  return floatStepUpIf(f, static_cast<std::uint32_t>(static_cast<double>(f) < v));
}

}  // namespace kerf::geometry
