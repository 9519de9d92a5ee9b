// uniformDiskIrradiance: the irradiance of a cap of uniform radiance, against quadrature of the cap
// itself, above, across and below the horizon.
#include "core/disk_irradiance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

#include "core/environment_lights.h"

namespace iblkit {
namespace {

constexpr double kPi = std::numbers::pi;

// Integral over the cap of angular radius r around c = (sin theta, 0, cos theta) of
// max(0, n.w) dw with n = +Z, by the midpoint rule in the cap's own polar coordinates.
double capQuadrature(double theta, double r) {
  const glm::dvec3 c(std::sin(theta), 0.0, std::cos(theta));
  const glm::dvec3 u(std::cos(theta), 0.0, -std::sin(theta)), v(0.0, 1.0, 0.0);
  constexpr int kRings = 600, kSegments = 1200;
  double sum = 0.0;
  for (int i = 0; i < kRings; ++i) {
    const double a0 = r * i / kRings, a1 = r * (i + 1) / kRings, a = 0.5 * (a0 + a1);
    const double ringSolidAngle = 2.0 * kPi * (std::cos(a0) - std::cos(a1)) / kSegments;
    for (int j = 0; j < kSegments; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kSegments;
      const glm::dvec3 w = std::cos(a) * c + std::sin(a) * (std::cos(phi) * u + std::sin(phi) * v);
      sum += std::max(0.0, w.z) * ringSolidAngle;
    }
  }
  return sum;
}

TEST(DiskIrradiance, AboveTheHorizonIsPiSinSquaredCosine) {
  for (const float r : {0.005f, 0.1f, 0.5f})
    for (const float theta : {0.0f, 0.3f, 1.0f}) {
      const float expected = float(kPi) * std::sin(r) * std::sin(r) * std::cos(theta);
      EXPECT_NEAR(uniformDiskIrradiance(std::cos(theta), r), expected, 1e-6f * expected) << r << " " << theta;
    }
}

TEST(DiskIrradiance, MatchesQuadratureOfTheCapAcrossTheHorizon) {
  for (const double r : {0.02, 0.2, 0.6, 1.2})
    for (const double offset : {-0.999, -0.7, -0.3, 0.0, 0.3, 0.7, 0.999}) {
      // theta from pi/2 - r (touching the horizon from above) to pi/2 + r (from below).
      const double theta = 0.5 * kPi + offset * r;
      const double expected = capQuadrature(theta, r);
      const double scale = kPi * std::sin(r) * std::sin(r);  // the facing value
      EXPECT_NEAR(uniformDiskIrradiance(float(std::cos(theta)), float(r)), expected, 2e-4 * scale)
          << "r " << r << " offset " << offset;
    }
}

TEST(DiskIrradiance, ZeroBelowTheHorizonAndForAPoint) {
  EXPECT_EQ(uniformDiskIrradiance(-0.5f, 0.3f), 0.0f);
  EXPECT_EQ(uniformDiskIrradiance(-1.0f, 0.3f), 0.0f);
  EXPECT_EQ(uniformDiskIrradiance(1.0f, 0.0f), 0.0f);
  // A hemisphere centred on the normal gives pi; one on the horizon, half of it.
  EXPECT_NEAR(uniformDiskIrradiance(1.0f, float(kPi) / 2.0f), float(kPi), 1e-5f);
  EXPECT_NEAR(uniformDiskIrradiance(0.0f, float(kPi) / 2.0f), float(kPi) / 2.0f, 1e-4f);
}

TEST(DiskIrradiance, IsContinuousWhereTheDiskMeetsTheHorizon) {
  const float r = 0.05f;
  const float theta = 0.5f * float(kPi) - r;
  const float above = uniformDiskIrradiance(std::cos(theta - 1e-4f), r);
  const float across = uniformDiskIrradiance(std::cos(theta + 1e-4f), r);
  EXPECT_NEAR(above, across, 2e-3f * float(kPi) * r * r);
}

TEST(DiskIrradiance, SunIrradianceIsTheLightsRadianceTimesTheDiskFactor) {
  EnvironmentLight light;
  light.direction = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));
  light.angularRadius = 0.01f;
  light.radiance = glm::vec3(1e4f, 2e4f, 3e4f);
  const glm::vec3 n(0.0f, 1.0f, 0.0f);
  const float factor = uniformDiskIrradiance(std::sqrt(0.5f), 0.01f);
  const glm::vec3 e = sunIrradiance(light, n);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(e[c], light.radiance[c] * factor);
  EXPECT_EQ(sunIrradiance(light, -n), glm::vec3(0.0f));
}

}  // namespace
}  // namespace iblkit
