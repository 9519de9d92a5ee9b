#include "core/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/gtc/constants.hpp>

#include "core/rng.h"
#include "support/chi2.h"

namespace iblkit {
namespace {

using test::Chi2Options;
using test::Chi2Result;

constexpr float kPi = glm::pi<float>();
constexpr int kChi2Tests = 8;  // chi-square runs in this file, for the Sidak correction

Chi2Options chi2Options(const std::string& name,
                        test::SphereBinning binning = test::SphereBinning::CosTheta) {
  Chi2Options o;
  o.name = name;
  o.testCount = kChi2Tests;
  o.sphereBinning = binning;
  return o;
}

// Checks invert(sample(u)) == u for many random u; `periodicY` compares u.y modulo 1 (the
// azimuth, whose seam at phi = 0 may come back as 0.9999999).
void expectRoundTrip(const std::function<glm::vec2(glm::vec2)>& roundTrip, bool periodicY,
                     float tolerance = 1e-4f) {
  PCG32 rng(3);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 u = rng.uniform2D();
    const glm::vec2 back = roundTrip(u);
    ASSERT_TRUE(back.x >= 0.0f && back.x < 1.0f && back.y >= 0.0f && back.y < 1.0f)
        << back.x << " " << back.y;
    float dy = std::abs(back.y - u.y);
    if (periodicY) dy = std::min(dy, 1.0f - dy);
    ASSERT_NEAR(back.x, u.x, tolerance) << "u = (" << u.x << ", " << u.y << ")";
    ASSERT_LE(dy, tolerance) << "u = (" << u.x << ", " << u.y << "), back.y = " << back.y;
  }
}

TEST(ConcentricDisk, MapsTheSquaresCentreEdgesAndCornerAsShirleyChiu) {
  const glm::vec2 centre = sampleUniformDiskConcentric({0.5f, 0.5f});
  EXPECT_EQ(centre, glm::vec2(0.0f));
  const glm::vec2 right = sampleUniformDiskConcentric({1.0f, 0.5f});
  EXPECT_NEAR(right.x, 1.0f, 1e-6f);
  EXPECT_NEAR(right.y, 0.0f, 1e-6f);
  const glm::vec2 top = sampleUniformDiskConcentric({0.5f, 1.0f});
  EXPECT_NEAR(top.x, 0.0f, 1e-6f);
  EXPECT_NEAR(top.y, 1.0f, 1e-6f);
  const glm::vec2 left = sampleUniformDiskConcentric({0.0f, 0.5f});
  EXPECT_NEAR(left.x, -1.0f, 1e-6f);
  EXPECT_NEAR(left.y, 0.0f, 1e-6f);
  // The square's corner goes to the circle at 45 degrees; a point halfway to the right edge to
  // radius 1/2.
  const glm::vec2 corner = sampleUniformDiskConcentric({1.0f, 1.0f});
  EXPECT_NEAR(corner.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(corner.y, std::sqrt(0.5f), 1e-6f);
  const glm::vec2 half = sampleUniformDiskConcentric({0.75f, 0.5f});
  EXPECT_NEAR(half.x, 0.5f, 1e-6f);
  EXPECT_NEAR(half.y, 0.0f, 1e-6f);
}

TEST(ConcentricDisk, IsUniformOverTheDisk) {
  // The disk scaled into [0,1]^2: density 1/pi per unit disk area becomes 4/pi.
  const Chi2Result r = test::chi2TestSquare(
      [](PCG32& rng) { return std::optional(0.5f * (sampleUniformDiskConcentric(rng.uniform2D()) + 1.0f)); },
      [](const glm::vec2& p) {
        const glm::vec2 d = 2.0f * p - 1.0f;
        return glm::dot(d, d) <= 1.0f ? 4.0 / glm::pi<double>() : 0.0;
      },
      chi2Options("concentric_disk"));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(ConcentricDisk, InverseRoundTrips) {
  expectRoundTrip(
      [](glm::vec2 u) { return invertUniformDiskConcentricSample(sampleUniformDiskConcentric(u)); }, false);
}

TEST(UniformHemisphere, PdfAndDistribution) {
  EXPECT_FLOAT_EQ(uniformHemispherePdf({0.0f, 0.0f, 1.0f}), 1.0f / (2.0f * kPi));
  EXPECT_FLOAT_EQ(uniformHemispherePdf({1.0f, 0.0f, 0.0f}), 1.0f / (2.0f * kPi));
  EXPECT_EQ(uniformHemispherePdf({0.0f, 0.6f, -0.8f}), 0.0f);
  const glm::vec3 w = sampleUniformHemisphere({0.6f, 0.25f});
  EXPECT_NEAR(w.x, 0.0f, 1e-6f);
  EXPECT_NEAR(w.y, 0.8f, 1e-6f);
  EXPECT_NEAR(w.z, 0.6f, 1e-6f);
  const Chi2Result r = test::chi2TestSphere(
      [](PCG32& rng) { return std::optional(sampleUniformHemisphere(rng.uniform2D())); },
      [](const glm::vec3& d) { return double(uniformHemispherePdf(d)); }, chi2Options("uniform_hemisphere"));
  EXPECT_TRUE(r.passed) << r.message;
  expectRoundTrip([](glm::vec2 u) { return invertUniformHemisphereSample(sampleUniformHemisphere(u)); },
                  true);
}

TEST(CosineHemisphere, PdfAndDistribution) {
  EXPECT_FLOAT_EQ(cosineHemispherePdf(0.5f), 0.5f / kPi);
  EXPECT_EQ(cosineHemispherePdf(-0.5f), 0.0f);
  const Chi2Result r = test::chi2TestSphere(
      [](PCG32& rng) { return std::optional(sampleCosineHemisphere(rng.uniform2D())); },
      [](const glm::vec3& d) { return double(cosineHemispherePdf(d.z)); }, chi2Options("cosine_hemisphere"));
  EXPECT_TRUE(r.passed) << r.message;
  expectRoundTrip([](glm::vec2 u) { return invertCosineHemisphereSample(sampleCosineHemisphere(u)); }, false);
}

TEST(UniformSphere, PdfAndDistribution) {
  EXPECT_FLOAT_EQ(uniformSpherePdf(), 1.0f / (4.0f * kPi));
  const Chi2Result r = test::chi2TestSphere(
      [](PCG32& rng) { return std::optional(sampleUniformSphere(rng.uniform2D())); },
      [](const glm::vec3&) { return double(uniformSpherePdf()); }, chi2Options("uniform_sphere"));
  EXPECT_TRUE(r.passed) << r.message;
  expectRoundTrip([](glm::vec2 u) { return invertUniformSphereSample(sampleUniformSphere(u)); }, true);
}

TEST(UniformCone, PdfAndDistribution) {
  EXPECT_FLOAT_EQ(uniformConePdf(0.9f, 0.5f), 1.0f / kPi);
  EXPECT_EQ(uniformConePdf(0.4f, 0.5f), 0.0f);
  // A wide cone (past the horizon) and a narrow one, binned in theta to resolve it.
  for (const float cosThetaMax : {-0.3f, 0.95f}) {
    const Chi2Result r = test::chi2TestSphere(
        [=](PCG32& rng) { return std::optional(sampleUniformCone(rng.uniform2D(), cosThetaMax)); },
        [=](const glm::vec3& d) { return double(uniformConePdf(d.z, cosThetaMax)); },
        chi2Options("uniform_cone_" + std::to_string(cosThetaMax), test::SphereBinning::Theta));
    EXPECT_TRUE(r.passed) << r.message;
    expectRoundTrip(
        [=](glm::vec2 u) { return invertUniformConeSample(sampleUniformCone(u, cosThetaMax), cosThetaMax); },
        true);
  }
}

TEST(CosinePowerLobe, PdfAndDistribution) {
  // Exponent 1 is the cosine lobe (density cos/pi), exponent 0 the uniform hemisphere.
  EXPECT_FLOAT_EQ(cosinePowerLobePdf(0.5f, 1.0f), cosineHemispherePdf(0.5f));
  EXPECT_FLOAT_EQ(cosinePowerLobePdf(0.5f, 0.0f), uniformHemispherePdf({0.0f, 0.0f, 1.0f}));
  EXPECT_FLOAT_EQ(cosinePowerLobePdf(0.5f, 20.0f), 21.0f / (2.0f * kPi) * std::pow(0.5f, 20.0f));
  EXPECT_EQ(cosinePowerLobePdf(-0.1f, 20.0f), 0.0f);
  const Chi2Result r = test::chi2TestSphere(
      [](PCG32& rng) { return std::optional(sampleCosinePowerLobe(rng.uniform2D(), 20.0f)); },
      [](const glm::vec3& d) { return double(cosinePowerLobePdf(d.z, 20.0f)); },
      chi2Options("cosine_power_20", test::SphereBinning::Theta));
  EXPECT_TRUE(r.passed) << r.message;
  expectRoundTrip(
      [](glm::vec2 u) { return invertCosinePowerLobeSample(sampleCosinePowerLobe(u, 20.0f), 20.0f); }, true);
}

TEST(UniformTriangle, IsUniformOverTheTriangle) {
  const glm::vec2 apex = sampleUniformTriangle({0.0f, 0.3f});
  EXPECT_EQ(apex, glm::vec2(1.0f, 0.0f));  // u.x = 0 is vertex 0 (b0 = 1)
  // Barycentrics (b0, b1) fill the half square b0 + b1 <= 1 with density 2.
  const Chi2Result r = test::chi2TestSquare(
      [](PCG32& rng) { return std::optional(sampleUniformTriangle(rng.uniform2D())); },
      [](const glm::vec2& b) { return b.x + b.y <= 1.0f ? 2.0 : 0.0; }, chi2Options("uniform_triangle"));
  EXPECT_TRUE(r.passed) << r.message;
  expectRoundTrip([](glm::vec2 u) { return invertUniformTriangleSample(sampleUniformTriangle(u)); }, false);
}

}  // namespace
}  // namespace iblkit
