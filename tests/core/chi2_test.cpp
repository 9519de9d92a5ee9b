// Tests of the chi-square harness itself (tests/support/chi2.h): it must accept correct samplers
// and reject wrong ones -- otherwise the sampler tests that rely on it prove nothing.

#include "support/chi2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/microfacet.h"
#include "core/sampling.h"

namespace iblkit::test {
namespace {

constexpr int kTests = 8;  // chi-square runs in this file, for the Sidak correction

Chi2Options options(const std::string& name) {
  Chi2Options o;
  o.name = name;
  o.testCount = kTests;
  return o;
}

std::optional<glm::vec3> cosineSample(PCG32& rng) { return sampleCosineHemisphere(rng.uniform2D()); }

TEST(ChiSquareUpperTail, KnownQuantiles) {
  // dof 2: exactly exp(-x/2).
  EXPECT_NEAR(chiSquareUpperTail(3.0, 2), std::exp(-1.5), 1e-12);
  // Tabulated critical values: chi2(0.95; 1) = 3.841459, chi2(0.99; 10) = 23.209251.
  EXPECT_NEAR(chiSquareUpperTail(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chiSquareUpperTail(23.209251, 10), 0.01, 1e-6);
  // Large dof, on both branches (series below the mean, continued fraction above); reference
  // values from a Simpson quadrature of the chi-square density.
  EXPECT_NEAR(chiSquareUpperTail(1000.0, 1000), 0.4940529, 1e-6);
  EXPECT_NEAR(chiSquareUpperTail(1200.0, 1000), 1.225594e-5, 1e-10);
  EXPECT_DOUBLE_EQ(chiSquareUpperTail(0.0, 5), 1.0);
}

TEST(Chi2Harness, AcceptsCosineSamplesAgainstTheirPdf) {
  const Chi2Result r = chi2TestSphere(
      cosineSample, [](const glm::vec3& w) { return cosineHemispherePdf(w.z); }, options("cosine_ok"));
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-4) << r.message;
  EXPECT_DOUBLE_EQ(r.sampleFraction, 1.0);
  EXPECT_GT(r.dof, 900);  // the upper half of the 61 x 31 bins
}

TEST(Chi2Harness, RejectsCosineSamplesAgainstTheUniformPdf) {
  const Chi2Result r = chi2TestSphere(cosineSample, uniformHemispherePdf, options("cosine_vs_uniform"));
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_LT(r.pValue, 1e-12);
  EXPECT_NE(r.message.find("the histogram does not match the pdf"), std::string::npos) << r.message;
}

TEST(Chi2Harness, RejectsASlightlyWrongGgxRoughness) {
  // Samples for alpha 0.5 checked against alpha 0.55: a 10% error in alpha must be seen.
  const glm::vec3 wo = glm::normalize(glm::vec3(0.5f, 0.0f, 1.0f));
  const Chi2Result r = chi2TestSphere(
      [&](PCG32& rng) { return std::optional(sampleGgxVisibleNormal(wo, 0.5f, rng.uniform2D())); },
      [&](const glm::vec3& wm) { return ggxVisibleNormalPdf(wo, wm, 0.55f); }, options("ggx_wrong_alpha"));
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_NE(r.message.find("the histogram does not match the pdf"), std::string::npos) << r.message;
}

TEST(Chi2Harness, RejectsSamplesWhereThePdfIsZero) {
  // Whole-sphere samples against a hemisphere pdf: half the samples land where the pdf is 0.
  const Chi2Result r =
      chi2TestSphere([](PCG32& rng) { return std::optional(sampleUniformSphere(rng.uniform2D())); },
                     uniformHemispherePdf, options("sphere_vs_hemisphere"));
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_NE(r.message.find("samples in bins where the integrated pdf is 0"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("samples where the pdf is 0"), std::string::npos) << r.message;
}

TEST(Chi2Harness, RejectsAPdfThatDoesNotIntegrateToTheSampleFraction) {
  // Correct shape, wrong normalisation (10% too large).
  const Chi2Result r = chi2TestSphere(
      cosineSample, [](const glm::vec3& w) { return 1.1 * cosineHemispherePdf(w.z); },
      options("cosine_scaled"));
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_NEAR(r.pdfIntegral, 1.1, 1e-3);
  EXPECT_NE(r.message.find("the pdf integrates to 1.10000 but 1.00000 of the calls produced a sample"),
            std::string::npos)
      << r.message;
}

TEST(Chi2Harness, AcceptsDecliningSamplersWhosePdfIntegratesToTheirSuccessRate) {
  // Keep only the samples with x > 0: the pdf, halved in support, integrates to 1/2.
  const Chi2Result r = chi2TestSquare(
      [](PCG32& rng) -> std::optional<glm::vec2> {
        const glm::vec2 u = rng.uniform2D();
        if (u.x < 0.5f) return std::nullopt;
        return u;
      },
      [](const glm::vec2& p) { return p.x >= 0.5f ? 1.0 : 0.0; }, options("half_square"));
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.pdfIntegral, 0.5, 1e-4);
  EXPECT_NEAR(r.sampleFraction, 0.5, 2e-3);
}

TEST(Chi2Harness, RejectsNonUnitDirectionsAndPointsOutsideTheSquare) {
  const Chi2Result sphere =
      chi2TestSphere([](PCG32& rng) { return std::optional(2.0f * sampleUniformSphere(rng.uniform2D())); },
                     [](const glm::vec3&) { return double(uniformSpherePdf()); }, options("long_directions"));
  EXPECT_FALSE(sphere.passed);
  EXPECT_NE(sphere.message.find("1000000 samples were not finite or outside the domain"), std::string::npos)
      << sphere.message;

  Chi2Options square = options("outside_square");
  square.sampleCount = 1000;
  const Chi2Result outside =
      chi2TestSquare([](PCG32& rng) { return std::optional(rng.uniform2D() + glm::vec2(1.5f)); },
                     [](const glm::vec2&) { return 1.0; }, square);
  EXPECT_FALSE(outside.passed);
  EXPECT_NE(outside.message.find("1000 samples were not finite or outside the domain"), std::string::npos)
      << outside.message;
}

}  // namespace
}  // namespace iblkit::test
