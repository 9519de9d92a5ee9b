#include "core/distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "support/chi2.h"

namespace iblkit {
namespace {

constexpr int kChi2Tests = 3;  // chi-square runs in this file, for the Sidak correction

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(PiecewiseConstant1D, SamplesProportionallyToTheFunction) {
  const std::vector<float> f = {1.0f, 0.0f, 3.0f, 4.0f};  // integral (1 + 0 + 3 + 4) / 4 = 2
  const PiecewiseConstant1D d(f);
  EXPECT_EQ(d.size(), 4);
  EXPECT_FLOAT_EQ(d.integral(), 2.0f);
  EXPECT_FLOAT_EQ(d.pdf(0.1f), 0.5f);
  EXPECT_FLOAT_EQ(d.pdf(0.3f), 0.0f);
  EXPECT_FLOAT_EQ(d.pdf(0.6f), 1.5f);
  EXPECT_FLOAT_EQ(d.pdf(0.9f), 2.0f);
  EXPECT_EQ(d.pdf(-0.1f), 0.0f);
  EXPECT_EQ(d.pdf(1.5f), 0.0f);
  // CDF 0, 1/8, 1/8, 4/8, 1: u = 1/16 is halfway through cell 0; u = 0.3 is 0.175/0.375 into cell 2.
  const PiecewiseConstant1D::Sample a = d.sample(1.0f / 16.0f);
  EXPECT_EQ(a.offset, 0);
  EXPECT_FLOAT_EQ(a.x, 0.125f);
  EXPECT_FLOAT_EQ(a.pdf, 0.5f);
  const PiecewiseConstant1D::Sample b = d.sample(0.3f);
  EXPECT_EQ(b.offset, 2);
  EXPECT_NEAR(b.x, (2.0f + 0.175f / 0.375f) / 4.0f, 1e-6f);
  EXPECT_FLOAT_EQ(b.pdf, 1.5f);
  // u exactly at the CDF step over the zero cell goes to the next cell with mass.
  EXPECT_EQ(d.sample(0.125f).offset, 2);
  EXPECT_LT(d.sample(std::nextafter(1.0f, 0.0f)).x, 1.0f);
}

TEST(PiecewiseConstant1D, NeverSamplesZeroCellsAndInvertRoundTrips) {
  const std::vector<float> f = {0.0f, 2.0f, 0.0f, 0.0f, 0.5f, 7.0f, 0.0f};
  const PiecewiseConstant1D d(f);
  double integral = 0.0;  // of the piecewise-constant pdf, cell by cell
  for (int i = 0; i < d.size(); ++i) integral += d.pdf((i + 0.5f) / d.size()) / d.size();
  EXPECT_NEAR(integral, 1.0, 1e-6);
  PCG32 rng(5u);
  for (int i = 0; i < 20000; ++i) {
    const float u = rng.uniformFloat();
    const PiecewiseConstant1D::Sample s = d.sample(u);
    ASSERT_GT(f[static_cast<std::size_t>(s.offset)], 0.0f);
    ASSERT_GT(s.pdf, 0.0f);
    ASSERT_FLOAT_EQ(s.pdf, d.pdf(s.x));
    ASSERT_NEAR(d.invert(s.x), u, 1e-5f);
  }
}

// sample() searches only near its guide entry; the cell it finds must be the one a binary search
// of the whole CDF finds: the last cell whose CDF start is <= u. Peaked functions (a sun among dim
// texels: many cells share a guide entry), runs of zeros and random ones; u at and just around
// the CDF values themselves.
TEST(PiecewiseConstant1D, GuidedSearchFindsTheCellOfAFullSearch) {
  PCG32 rng(17, 3);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 1 + static_cast<int>(rng.uniformFloat() * 600.0f);
    std::vector<float> f(static_cast<std::size_t>(n));
    for (float& v : f) {
      const float r = rng.uniformFloat();
      v = trial % 3 == 0 ? (r < 0.01f ? 1e5f : 0.01f * r) : trial % 3 == 1 ? (r < 0.5f ? 0.0f : r) : r;
    }
    const PiecewiseConstant1D d(f);
    const std::span<const float> cdf = d.cdf();
    ASSERT_EQ(cdf.size(), static_cast<std::size_t>(n) + 1);
    std::vector<float> us;
    for (int i = 0; i < 2000; ++i) us.push_back(rng.uniformFloat());
    for (const float c : cdf)
      for (const float u : {c, std::nextafter(c, 0.0f), std::nextafter(c, 1.0f)})
        if (u >= 0.0f && u < 1.0f) us.push_back(u);
    for (const float u : us) {
      const int full = static_cast<int>(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin()) - 1;
      ASSERT_EQ(d.sample(u).offset, std::clamp(full, 0, n - 1))
          << "trial " << trial << ", n " << n << ", u " << u;
    }
  }
}

TEST(PiecewiseConstant1D, AllZeroFunctionIsUniform) {
  const std::vector<float> f(5, 0.0f);
  const PiecewiseConstant1D d(f);
  EXPECT_EQ(d.integral(), 0.0f);
  EXPECT_EQ(d.pdf(0.7f), 1.0f);
  const PiecewiseConstant1D::Sample s = d.sample(0.7f);
  EXPECT_NEAR(s.x, 0.7f, 1e-6f);
  EXPECT_EQ(s.pdf, 1.0f);
  EXPECT_EQ(s.offset, 3);
  EXPECT_NEAR(d.invert(0.7f), 0.7f, 1e-6f);
}

TEST(PiecewiseConstant1D, RejectsBadValues) {
  EXPECT_EQ(errorOf([] { PiecewiseConstant1D d(std::vector<float>{}); }),
            "PiecewiseConstant1D: no function values");
  EXPECT_EQ(errorOf([] {
              PiecewiseConstant1D d(std::vector<float>{1.0f, -2.0f});
            }),
            "PiecewiseConstant1D: value 1 is -2 (must be finite and non-negative)");
  EXPECT_EQ(
      errorOf([] { PiecewiseConstant1D d(std::vector<float>{std::numeric_limits<float>::quiet_NaN()}); }),
      "PiecewiseConstant1D: value 0 is nan (must be finite and non-negative)");
  EXPECT_EQ(errorOf([] {
              PiecewiseConstant1D d(std::vector<float>{0.0f, 0.0f, std::numeric_limits<float>::infinity()});
            }),
            "PiecewiseConstant1D: value 2 is inf (must be finite and non-negative)");
}

TEST(PiecewiseConstant2D, RejectsBadValuesAndSizes) {
  const std::vector<float> six(6, 1.0f);
  EXPECT_EQ(errorOf([&] { PiecewiseConstant2D d(six, 4, 2); }),
            "PiecewiseConstant2D: 6 values for a 4 x 2 grid");
  EXPECT_EQ(errorOf([&] { PiecewiseConstant2D d(six, 0, 6); }),
            "PiecewiseConstant2D: grid size 0 x 6 is empty");
  std::vector<float> bad = six;
  bad[4] = -1.0f;
  EXPECT_EQ(errorOf([&] { PiecewiseConstant2D d(bad, 3, 2); }),
            "PiecewiseConstant2D: value at column 1, row 1 is -1 (must be finite and non-negative)");
}

// A 6 x 4 grid: its cell edges are at least 1/6 of a bin away from the harness's 61 x 31 bin edges,
// so the quadrature resolves every bin the function's steps cut.
constexpr int kWidth = 6, kHeight = 4;

test::Chi2Result chi2Of(const PiecewiseConstant2D& d, const std::string& name) {
  test::Chi2Options options;
  options.name = name;
  options.testCount = kChi2Tests;
  return test::chi2TestSquare([&](PCG32& rng) { return std::optional(d.sample(rng.uniform2D()).p); },
                              [&](const glm::vec2& p) { return double(d.pdf(p)); }, options);
}

TEST(PiecewiseConstant2D, RandomFunctionIsSampledByItsPdf) {
  PCG32 rng(21u);
  std::vector<float> f(kWidth * kHeight);
  for (float& v : f) v = rng.uniformFloat() < 0.2f ? 0.0f : 10.0f * rng.uniformFloat();
  const PiecewiseConstant2D d(f, kWidth, kHeight);
  EXPECT_EQ(d.width(), kWidth);
  EXPECT_EQ(d.height(), kHeight);
  double sum = 0.0;
  for (const float v : f) sum += v;
  EXPECT_NEAR(d.integral(), sum / (kWidth * kHeight), 1e-5);
  const test::Chi2Result r = chi2Of(d, "piecewise2d_random");
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-4) << r.message;
  // The pdf at a sample is the sample's pdf, f / integral; invert round trips.
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 u = rng.uniform2D();
    const PiecewiseConstant2D::Sample s = d.sample(u);
    const float value = f[static_cast<std::size_t>(s.offset.y * kWidth + s.offset.x)];
    ASSERT_FLOAT_EQ(s.pdf, value / d.integral());
    ASSERT_FLOAT_EQ(d.pdf(s.p), s.pdf);
    const glm::vec2 back = d.invert(s.p);
    ASSERT_NEAR(back.x, u.x, 1e-5f);
    ASSERT_NEAR(back.y, u.y, 1e-5f);
  }
}

TEST(PiecewiseConstant2D, OneHotFunctionSamplesOnlyItsCell) {
  std::vector<float> f(kWidth * kHeight, 0.0f);
  f[2 * kWidth + 4] = 3.0f;  // column 4, row 2
  const PiecewiseConstant2D d(f, kWidth, kHeight);
  EXPECT_FLOAT_EQ(d.pdf({4.5f / kWidth, 2.5f / kHeight}), float(kWidth * kHeight));
  EXPECT_EQ(d.pdf({0.1f, 0.1f}), 0.0f);
  const PiecewiseConstant2D::Sample s = d.sample({0.0f, 0.999f});
  EXPECT_EQ(s.offset, glm::ivec2(4, 2));
  const test::Chi2Result r = chi2Of(d, "piecewise2d_one_hot");
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-4) << r.message;
}

TEST(PiecewiseConstant2D, AllZeroFunctionIsUniform) {
  const std::vector<float> f(kWidth * kHeight, 0.0f);
  const PiecewiseConstant2D d(f, kWidth, kHeight);
  EXPECT_EQ(d.pdf({0.3f, 0.8f}), 1.0f);
  const test::Chi2Result r = chi2Of(d, "piecewise2d_all_zero");
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace iblkit
