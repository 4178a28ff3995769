// The outward roundings of doubles to floats (geometry/float_steps.h) against what the library
// gives: a cast corrected by std::nextafter, and one float step more. The self-intersection sweeps'
// boxes are made with them, and a box rounded one float too tight could drop a pair that meets.
#include "kerf/geometry/float_steps.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace kerf::geometry {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

float libraryBelow(double v) {
  const auto f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -kInf) : f;
}
float libraryAbove(double v) {
  const auto f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, kInf) : f;
}

/// Doubles at the edges (zeros of both signs, the least subnormals, the floats' largest, past
/// them, infinities) and random ones: any bits, and floats with the doubles just either side.
std::vector<double> samples() {
  constexpr double kMaxFloat = std::numeric_limits<float>::max();
  constexpr double kDenorm = std::numeric_limits<float>::denorm_min();
  std::vector<double> v = {0.0,
                           -0.0,
                           kDenorm,
                           -kDenorm,
                           kDenorm / 3,
                           -kDenorm / 3,
                           kMaxFloat,
                           -kMaxFloat,
                           3.5e38,
                           -3.5e38,
                           1e300,
                           -1e300,
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::denorm_min(),
                           0.1,
                           -0.1,
                           5000.0001,
                           -4999.9999};
  std::mt19937_64 random(13);
  for (int i = 0; i < 200000; ++i) {
    const double d = std::bit_cast<double>(random());
    if (!std::isnan(d)) v.push_back(d);
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
    if (std::isnan(f)) continue;
    v.push_back(f);
    v.push_back(std::nextafter(static_cast<double>(f), 1e300));
    v.push_back(std::nextafter(static_cast<double>(f), -1e300));
  }
  return v;
}

/// The float at least one step below v that the sweeps' boxes need: the greatest float not above
/// v, and the float next below that.
float oneStepBelow(double v) {
  const float below = libraryBelow(v);
  return below == -kInf ? below : std::nextafter(below, -kInf);
}
float oneStepAbove(double v) {
  const float above = libraryAbove(v);
  return above == kInf ? above : std::nextafter(above, kInf);
}

TEST(float_steps_test, a_double_is_rounded_more_than_a_float_step_outwards_and_not_much_more) {
  constexpr double kMaxFloat = std::numeric_limits<float>::max();
  std::size_t compared = 0, inRange = 0;
  for (const double d : samples()) {
    const float below = floatWellBelow(d), above = floatWellAbove(d);
    ASSERT_FALSE(std::isnan(below)) << d;
    ASSERT_FALSE(std::isnan(above)) << d;
    ASSERT_LE(below, oneStepBelow(d)) << d;
    ASSERT_GE(above, oneStepAbove(d)) << d;
    ++compared;
    // Within the floats' range, a few float steps from v: 2^-20 of it, or 2^-125 near zero.
    if (std::abs(d) * (1 + 0x1p-20) + 0x1p-125 >= kMaxFloat) continue;
    const double room = std::abs(d) * 0x1p-20 + 0x1p-125;
    ASSERT_GE(static_cast<double>(below), d - room) << d;
    ASSERT_LE(static_cast<double>(above), d + room) << d;
    ++inRange;
  }
  EXPECT_GT(compared, 600000u);
  EXPECT_GT(inRange, 300000u);
  // Past the floats' range: the float next inside the largest, or an infinity beyond it.
  const float top = std::nextafter(std::numeric_limits<float>::max(), 0.0f);
  EXPECT_EQ(floatWellBelow(1e300), top);
  EXPECT_EQ(floatWellBelow(std::numeric_limits<double>::infinity()), top);
  EXPECT_EQ(floatWellAbove(-1e300), -top);
  EXPECT_EQ(floatWellBelow(-1e300), -kInf);
  EXPECT_EQ(floatWellAbove(1e300), kInf);
  // Either zero: below the least normal float of the other sign.
  EXPECT_LE(floatWellBelow(0.0), -std::numeric_limits<float>::min());
  EXPECT_GE(floatWellAbove(-0.0), std::numeric_limits<float>::min());
}

}  // namespace
}  // namespace kerf::geometry
