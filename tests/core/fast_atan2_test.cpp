#include "core/fast_atan2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/rng.h"

namespace iblkit {
namespace {

// Against atan2 in double precision: every angle on a fine circle, at lengths from 1e-30 to 1e30,
// and random points. Near +-pi a float's ulp is 2.4e-7, so even libm's atan2f is 1.2e-7 off there;
// the polynomial adds at most about as much again.
TEST(FastAtan2, MatchesAtan2WithinAFewTenthsOfAMicroradian) {
  double worst = 0.0, libm = 0.0;
  for (const float length : {1e-30f, 1e-3f, 1.0f, 7.5f, 1e30f})
    for (int i = 0; i < 100000; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / 100000.0 - std::numbers::pi;
      const float y = length * static_cast<float>(std::sin(angle)), x = length * static_cast<float>(std::cos(angle));
      worst = std::max(worst, std::abs(double(fastAtan2(y, x)) - std::atan2(double(y), double(x))));
      libm = std::max(libm, std::abs(double(std::atan2(y, x)) - std::atan2(double(y), double(x))));
    }
  PCG32 rng(4, 2);
  for (int i = 0; i < 1000000; ++i) {
    const float y = 2.0f * rng.uniformFloat() - 1.0f, x = 2.0f * rng.uniformFloat() - 1.0f;
    worst = std::max(worst, std::abs(double(fastAtan2(y, x)) - std::atan2(double(y), double(x))));
  }
  EXPECT_LT(worst, 3e-7);
  EXPECT_LT(worst, libm + 1.6e-7) << "libm's atan2f: " << libm;
  EXPECT_GT(worst, 0.0);  // it is an approximation: a test that compares libm with itself would pass 0
}

TEST(FastAtan2, AxesSignedZerosAndNaNAsStdAtan2) {
  const float pi = std::numbers::pi_v<float>;
  EXPECT_EQ(fastAtan2(0.0f, 1.0f), 0.0f);
  EXPECT_NEAR(fastAtan2(1.0f, 0.0f), 0.5f * pi, 1e-7f);
  EXPECT_NEAR(fastAtan2(-1.0f, 0.0f), -0.5f * pi, 1e-7f);
  EXPECT_EQ(fastAtan2(0.0f, -1.0f), pi);
  EXPECT_EQ(fastAtan2(-0.0f, -1.0f), -pi);
  EXPECT_NEAR(fastAtan2(1.0f, 1.0f), 0.25f * pi, 1e-7f);
  for (const float y : {0.0f, -0.0f})
    for (const float x : {0.0f, -0.0f}) {
      const float expected = std::atan2(y, x), got = fastAtan2(y, x);
      EXPECT_EQ(got, expected) << y << "," << x;
      EXPECT_EQ(std::signbit(got), std::signbit(expected)) << y << "," << x;
    }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isnan(fastAtan2(nan, 1.0f)));
  EXPECT_TRUE(std::isnan(fastAtan2(1.0f, nan)));
  EXPECT_TRUE(std::isnan(fastAtan2(0.0f, nan)));
}

}  // namespace
}  // namespace iblkit
