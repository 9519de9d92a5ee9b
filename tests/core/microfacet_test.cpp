#include "core/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/rng.h"
#include "support/chi2.h"

namespace iblkit {
namespace {

constexpr double kPi = glm::pi<double>();
constexpr int kChi2Tests = 6;  // chi-square runs in this file, for the Sidak correction

glm::vec3 directionAt(float thetaDegrees, float phiDegrees = 0.0f) {
  const float theta = glm::radians(thetaDegrees), phi = glm::radians(phiDegrees);
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(Ggx, DistributionValues) {
  // At the normal D = 1 / (pi alpha^2); alpha = 1 is uniform over the hemisphere, 1/pi.
  EXPECT_FLOAT_EQ(ggxD({0.0f, 0.0f, 1.0f}, 0.5f), float(1.0 / (kPi * 0.25)));
  EXPECT_FLOAT_EQ(ggxD(directionAt(50.0f, 10.0f), 1.0f), float(1.0 / kPi));
  EXPECT_EQ(ggxD({0.0f, 0.6f, -0.8f}, 0.5f), 0.0f);
  // glTF's form alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2) at 30 degrees, alpha 0.3.
  const float c = std::cos(glm::radians(30.0f)), a2 = 0.09f;
  const float t = c * c * (a2 - 1.0f) + 1.0f;
  EXPECT_NEAR(ggxD(directionAt(30.0f), 0.3f), a2 / (float(kPi) * t * t), 1e-5f);
}

TEST(Ggx, ProjectedAreaIsOne) {
  // integral of D(wm) cos(theta_m) over the hemisphere = 2 pi int_0^1 D(mu) mu dmu = 1, by midpoint
  // quadrature in mu with enough points to resolve a sharp peak at mu = 1.
  for (const float alpha : {0.02f, 0.2f, 0.7f, 1.0f}) {
    const int n = 400000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double mu = (i + 0.5) / n;
      const glm::vec3 wm(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu));
      sum += ggxD(wm, alpha) * mu;
    }
    EXPECT_NEAR(2.0 * kPi * sum / n, 1.0, 2e-3) << "alpha " << alpha;
  }
}

TEST(Ggx, MaskingValues) {
  // Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2: at 60 degrees with alpha 1, tan^2 = 3, Lambda = 1/2.
  EXPECT_NEAR(ggxLambda(directionAt(60.0f), 1.0f), 0.5f, 1e-6f);
  EXPECT_NEAR(ggxG1(directionAt(60.0f), 1.0f), 2.0f / 3.0f, 1e-6f);
  EXPECT_EQ(ggxLambda({0.0f, 0.0f, 1.0f}, 0.5f), 0.0f);
  EXPECT_EQ(ggxG1({0.0f, 0.0f, 1.0f}, 0.5f), 1.0f);
  EXPECT_EQ(ggxG1({1.0f, 0.0f, 0.0f}, 0.5f), 0.0f);
  // Small alpha tan: Lambda ~ alpha^2 tan^2 / 4 = 7.8e-9, where sqrt(1 + e) - 1 would round to 0.
  const float expected = 1e-6f * std::pow(std::tan(glm::radians(10.0f)), 2.0f) / 4.0f;
  EXPECT_NEAR(ggxLambda(directionAt(10.0f), 1e-3f), expected, 1e-5f * expected);
}

TEST(Ggx, SmithVisibilityIsTheHeightCorrelatedG2) {
  // glTF's closed form equals G2 / (4 cosI cosO) with G2 = 1 / (1 + Lambda(wi) + Lambda(wo)).
  for (const float alpha : {0.05f, 0.4f, 1.0f}) {
    for (const float thetaI : {0.0f, 40.0f, 85.0f}) {
      for (const float thetaO : {10.0f, 60.0f, 89.0f}) {
        const glm::vec3 wi = directionAt(thetaI), wo = directionAt(thetaO, 120.0f);
        const float g2 = 1.0f / (1.0f + ggxLambda(wi, alpha) + ggxLambda(wo, alpha));
        const float expected = g2 / (4.0f * wi.z * wo.z);
        EXPECT_NEAR(ggxSmithVisibility(wi.z, wo.z, alpha), expected, 1e-5f * expected)
            << alpha << " " << thetaI << " " << thetaO;
      }
    }
  }
  // Symmetric in its arguments (reciprocity).
  EXPECT_EQ(ggxSmithVisibility(0.3f, 0.8f, 0.2f), ggxSmithVisibility(0.8f, 0.3f, 0.2f));
}

struct VndfCase {
  float alpha, thetaO;
};

void PrintTo(const VndfCase& c, std::ostream* os) { *os << "alpha " << c.alpha << ", theta_o " << c.thetaO; }

class GgxVisibleNormals : public ::testing::TestWithParam<VndfCase> {};

TEST_P(GgxVisibleNormals, SamplesFollowThePdf) {
  const auto [alpha, thetaO] = GetParam();
  const glm::vec3 wo = directionAt(thetaO, 30.0f);
  test::Chi2Options options;
  options.name = "ggx_vndf_alpha" + std::to_string(alpha) + "_theta" + std::to_string(thetaO);
  options.testCount = kChi2Tests;
  options.sphereBinning = test::SphereBinning::Theta;
  const test::Chi2Result r = test::chi2TestSphere(
      [&](PCG32& rng) { return std::optional(sampleGgxVisibleNormal(wo, alpha, rng.uniform2D())); },
      [&](const glm::vec3& wm) { return double(ggxVisibleNormalPdf(wo, wm, alpha)); }, options);
  EXPECT_TRUE(r.passed) << r.message;
  // The visible normals' projected area is wo's: the pdf integrates to 1.
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-3) << r.message;
}

TEST_P(GgxVisibleNormals, InverseRoundTrips) {
  const auto [alpha, thetaO] = GetParam();
  const glm::vec3 wo = directionAt(thetaO, 30.0f);
  PCG32 rng(9u);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 u = rng.uniform2D();
    const glm::vec3 wm = sampleGgxVisibleNormal(wo, alpha, u);
    const glm::vec2 back = invertGgxVisibleNormalSample(wo, wm, alpha);
    ASSERT_NEAR(back.x, u.x, 1e-4f) << "u = (" << u.x << ", " << u.y << ")";
    ASSERT_NEAR(back.y, u.y, 1e-4f) << "u = (" << u.x << ", " << u.y << ")";
  }
}

// Rough and fairly smooth, at normal, oblique and grazing incidence.
INSTANTIATE_TEST_SUITE_P(Cases, GgxVisibleNormals,
                         ::testing::Values(VndfCase{0.1f, 0.0f}, VndfCase{0.1f, 60.0f}, VndfCase{0.5f, 30.0f},
                                           VndfCase{0.5f, 89.0f}, VndfCase{1.0f, 0.0f},
                                           VndfCase{1.0f, 75.0f}));

}  // namespace
}  // namespace iblkit
