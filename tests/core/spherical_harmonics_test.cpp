#include "core/spherical_harmonics.h"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

constexpr int kGrid = 256;

TEST(SphericalHarmonics, BasisIsOrthonormal) {
  for (int j = 0; j < kShCoefficients; ++j) {
    // Project the basis function Y_j itself: the result must be the unit vector e_j.
    const SphericalHarmonics9 sh =
        projectSh9([j](const glm::vec3& d) { return glm::vec3(shBasis9(d)[j]); }, kGrid);
    for (int k = 0; k < kShCoefficients; ++k)
      EXPECT_NEAR(sh.coefficients[k].x, j == k ? 1.0f : 0.0f, 2e-4f) << "j=" << j << " k=" << k;
  }
}

TEST(SphericalHarmonics, ProjectionRecoversAnSh9Function) {
  SphericalHarmonics9 truth;
  for (int k = 0; k < kShCoefficients; ++k)
    truth.coefficients[k] = glm::vec3(0.1f * k - 0.3f, 0.5f, k % 2 ? 1.0f : -1.0f);
  const SphericalHarmonics9 sh = projectSh9([&](const glm::vec3& d) { return truth.evaluate(d); }, kGrid);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh.coefficients[k][c], truth.coefficients[k][c], 5e-4f);
}

TEST(SphericalHarmonics, ConstantRadianceGivesIrradiancePi) {
  const SphericalHarmonics9 sh = projectSh9([](const glm::vec3&) { return glm::vec3(1.0f); }, kGrid);
  EXPECT_NEAR(sh.coefficients[0].x, 2.0f * std::sqrt(glm::pi<float>()), 1e-3f);  // 4pi * Y_00
  for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, -2, 3))})
    EXPECT_NEAR(sh.irradiance(n).y, glm::pi<float>(), 1e-3f);
}

TEST(SphericalHarmonics, IrradianceOfLinearRadianceMatchesClosedForm) {
  // L(w) = max(0, w.y) would ring; L(w) = 1 + w.y lies in band <= 1, so SH9 is exact:
  // E(n) = integral (1 + w.y) max(0, n.w) dw = pi + (2pi/3) n.y.
  const SphericalHarmonics9 sh = projectSh9([](const glm::vec3& d) { return glm::vec3(1.0f + d.y); }, kGrid);
  for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 1, 0))}) {
    const float expected = glm::pi<float>() + 2.0f * glm::pi<float>() / 3.0f * n.y;
    EXPECT_NEAR(sh.irradiance(n).x, expected, 2e-3f);
  }
}

TEST(SphericalHarmonics, IrradianceOfQuadraticRadianceMatchesClosedForm) {
  // L(w) = w.y^2 = (1/3) + band-2 zonal term. E(n) for n = +Y: integral over the upper
  // hemisphere of cos^3 = 2pi/4 = pi/2.
  const SphericalHarmonics9 sh = projectSh9([](const glm::vec3& d) { return glm::vec3(d.y * d.y); }, kGrid);
  EXPECT_NEAR(sh.irradiance(glm::vec3(0, 1, 0)).x, glm::pi<float>() / 2.0f, 2e-3f);
  // n = +X: integral of y^2 max(0, x) dw = pi/4.
  EXPECT_NEAR(sh.irradiance(glm::vec3(1, 0, 0)).x, glm::pi<float>() / 4.0f, 2e-3f);
}

TEST(SphericalHarmonics, WindowKeepsBandZeroAndDampsHigherBands) {
  SphericalHarmonics9 sh;
  for (glm::vec3& c : sh.coefficients) c = glm::vec3(1.0f);
  const SphericalHarmonics9 w = windowSh9(sh, 3.0f);
  EXPECT_FLOAT_EQ(w.coefficients[0].x, 1.0f);
  const float x1 = glm::pi<float>() / 3.0f, s1 = std::sin(x1) / x1;
  EXPECT_NEAR(w.coefficients[2].x, s1 * s1 * s1 * s1, 1e-6f);
  EXPECT_LT(w.coefficients[6].x, w.coefficients[2].x);
  EXPECT_FLOAT_EQ(windowSh9(sh, 2.0f).coefficients[8].x, 0.0f);  // band 2 cut off
  EXPECT_FLOAT_EQ(windowSh9(sh, 0.0f).coefficients[8].x, 1.0f);  // no window
}

}  // namespace
}  // namespace iblkit
