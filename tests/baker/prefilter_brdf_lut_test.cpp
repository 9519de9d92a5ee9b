#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "baker/brdf_lut.h"
#include "bakefile/brdf_lut_exr.h"
#include "core/image_io.h"
#include "core/microfacet.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// (A, B) by the midpoint rule over the hemisphere of l in (theta, phi) with the BRDF evaluated
// directly (D, height-correlated visibility, Schlick's (1 - V.H)^5): no importance sampling.
glm::vec2 dfgByQuadrature(float NoV, float roughness) {
  const float pi = glm::pi<float>();
  const float alpha = roughness * roughness;
  const glm::vec3 v(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
  const int thetaSteps = 1024, phiSteps = 1024;
  double a = 0.0, b = 0.0;
  for (int i = 0; i < thetaSteps; ++i) {
    const float theta0 = 0.5f * pi * static_cast<float>(i) / thetaSteps;
    const float theta1 = 0.5f * pi * static_cast<float>(i + 1) / thetaSteps;
    const float theta = 0.5f * (theta0 + theta1);
    const float cellSolidAngle = (2.0f * pi / phiSteps) * (std::cos(theta0) - std::cos(theta1));
    for (int j = 0; j < phiSteps; ++j) {
      const float phi = 2.0f * pi * (static_cast<float>(j) + 0.5f) / phiSteps;
      const glm::vec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const glm::vec3 h = glm::normalize(v + l);
      const float f = ggxD(h, alpha) * ggxSmithVisibility(l.z, NoV, alpha) * l.z * cellSolidAngle;
      const float fresnel = std::pow(1.0f - glm::dot(v, h), 5.0f);
      a += (1.0f - fresnel) * f;
      b += fresnel * f;
    }
  }
  return {static_cast<float>(a), static_cast<float>(b)};
}

TEST(BrdfLut, MatchesADirectQuadratureWithinOnePercent) {
  for (const float roughness : {0.3f, 0.6f, 0.9f})
    for (const float NoV : {0.1f, 0.5f, 0.9f}) {
      const glm::vec3 sampled = integrateDfg(NoV, roughness, 512);
      const glm::vec2 exact = dfgByQuadrature(NoV, roughness);
      // Within 1% of the albedo E = A + B (B alone is ~1e-4 near normal incidence).
      const float tolerance = 0.01f * (exact.x + exact.y);
      EXPECT_NEAR(sampled.x, exact.x, tolerance) << "NoV " << NoV << " roughness " << roughness;
      EXPECT_NEAR(sampled.y, exact.y, tolerance) << "NoV " << NoV << " roughness " << roughness;
      EXPECT_FLOAT_EQ(sampled.z, sampled.x + sampled.y);
    }
}

TEST(BrdfLut, SmoothSurfaceSeenHeadOnReflectsEverything) {
  const glm::vec3 dfg = integrateDfg(1.0f, 0.01f, 512);
  EXPECT_NEAR(dfg.z, 1.0f, 1e-3f);
  EXPECT_NEAR(dfg.y, 0.0f, 1e-6f);  // (1 - V.H)^5 = 0 with h = n = v
}

TEST(BrdfLut, RoughestLobeSeenHeadOnHasTheClosedFormAlbedo) {
  // alpha = 1: D = 1/pi and V = 0.5 / (NoL + 1) at NoV = 1, so
  // E = integral (1/pi) 0.5 NoL / (NoL + 1) dl = integral_0^1 mu / (1 + mu) dmu = 1 - ln 2.
  EXPECT_NEAR(integrateDfg(1.0f, 1.0f, 512).z, 1.0f - std::log(2.0f), 0.01f * (1.0f - std::log(2.0f)));
}

TEST(BrdfLut, TableLayoutValuesAndTrends) {
  const int size = 32;
  const Image lut = computeBrdfLut(size, 512);
  ASSERT_EQ(lut.width(), size);
  ASSERT_EQ(lut.height(), size);
  // Texel centres: (x, y) -> NoV = (x + 0.5) / size, roughness = (y + 0.5) / size.
  const glm::vec3 texel(lut.at(12, 20));
  const glm::vec3 direct = integrateDfg(12.5f / size, 20.5f / size, 512);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(texel[c], direct[c]);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec4 p = lut.at(x, y);
      EXPECT_GE(p.r, 0.0f);
      EXPECT_GE(p.g, 0.0f);
      EXPECT_LE(p.b, 1.0f + 1e-4f) << x << " " << y;
      EXPECT_EQ(p.a, 1.0f);
      // Energy lost to single scattering grows with roughness (away from grazing angles, where
      // the height-correlated albedo of rough lobes rises again: E -> 1 as NoV -> 0 at alpha = 1)...
      if (y > 0 && x >= size / 8) {
        EXPECT_LE(p.b, lut.at(x, y - 1).b + 2e-3f) << x << " " << y;
      }
      // ...and Fresnel's share (B) shrinks towards normal incidence.
      if (x > 0) {
        EXPECT_LE(p.g, lut.at(x - 1, y).g + 2e-3f) << x << " " << y;
      }
    }
  EXPECT_GT(lut.at(size - 1, 0).b, 0.99f);
}

TEST(BrdfLut, WritesAFloatExr) {
  const Image lut = computeBrdfLut(8, 64);
  const std::filesystem::path file = test::scratchDir() / "brdf_lut.exr";
  writeBrdfLutExr(file, lut);
  const Image read = readExr(file);
  ASSERT_EQ(read.width(), 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(read.at(x, y), lut.at(x, y));
}

TEST(BrdfLut, RefusesEmptyTables) {
  EXPECT_THROW(computeBrdfLut(0, 16), std::invalid_argument);
  EXPECT_THROW(computeBrdfLut(16, 0), std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
