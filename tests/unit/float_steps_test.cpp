// The branch-free float steps and directed roundings (geometry/float_steps.h) against what the
// library gives: std::nextafter, and a cast corrected by it. The self-intersection sweeps' boxes
// are made with them, and a box rounded the wrong way by one float could drop a pair that meets.
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

std::uint32_t bitsOf(float f) { return std::bit_cast<std::uint32_t>(f); }

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

TEST(float_steps_test, a_step_is_the_librarys_next_float_and_no_step_is_the_float_itself) {
  std::size_t compared = 0;
  for (const double d : samples()) {
    const auto f = static_cast<float>(d);
    ASSERT_EQ(bitsOf(floatStepDownIf(f, 0)), bitsOf(f)) << d;
    ASSERT_EQ(bitsOf(floatStepUpIf(f, 0)), bitsOf(f)) << d;
    if (f != -kInf) {
      ASSERT_EQ(bitsOf(floatStepDownIf(f, 1)), bitsOf(std::nextafter(f, -kInf))) << d;
    }
    if (f != kInf) {
      ASSERT_EQ(bitsOf(floatStepUpIf(f, 1)), bitsOf(std::nextafter(f, kInf))) << d;
    }
    ++compared;
  }
  EXPECT_GT(compared, 600000u);
  // Either zero steps to the least float of the other sign, and back to a zero.
  EXPECT_EQ(floatStepDownIf(0.0f, 1), -std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(floatStepDownIf(-0.0f, 1), -std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(floatStepUpIf(-0.0f, 1), std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(floatStepDownIf(kInf, 1), std::numeric_limits<float>::max());
}

TEST(float_steps_test, a_double_is_rounded_down_and_up_to_the_floats_either_side) {
  for (const double d : samples()) {
    const float below = floatBelow(d), above = floatAbove(d);
    ASSERT_EQ(bitsOf(below), bitsOf(libraryBelow(d))) << d;
    ASSERT_EQ(bitsOf(above), bitsOf(libraryAbove(d))) << d;
    ASSERT_LE(static_cast<double>(below), d) << d;
    ASSERT_GE(static_cast<double>(above), d) << d;
  }
  EXPECT_EQ(floatBelow(1e300), std::numeric_limits<float>::max());
  EXPECT_EQ(floatAbove(-1e300), -std::numeric_limits<float>::max());
  EXPECT_EQ(floatBelow(0.1), std::nextafter(0.1f, 0.0f));  // 0.1f lies above 0.1
  EXPECT_EQ(floatAbove(0.1), 0.1f);
}

}  // namespace
}  // namespace kerf::geometry
