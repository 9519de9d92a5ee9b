// residualTruncationCube (engine/gl/residual_truncation.h): the residual's irradiance cube minus its
// SH9 irradiance, texel by texel, along each texel's centre direction.
#include "engine/gl/residual_truncation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace iblkit {
namespace {

// An SH9 whose irradiance is lopsided (bands 0, 1 and 2 all set) and negative in places.
SphericalHarmonics9 lopsidedSh9() {
  SphericalHarmonics9 sh;
  sh.coefficients[0] = glm::vec3(1.0f, 0.8f, 0.6f);
  sh.coefficients[1] = glm::vec3(0.9f, 0.7f, 0.5f);
  sh.coefficients[3] = glm::vec3(-0.6f, -0.4f, -0.2f);
  sh.coefficients[6] = glm::vec3(0.5f, 0.3f, 0.1f);
  sh.coefficients[8] = glm::vec3(-0.3f, 0.2f, 0.4f);
  return sh;
}

// A cube that is exactly the SH9's (clamped) irradiance at its texel centres leaves nothing: the
// texel directions are the cube's own (a face or axis mixed up would leave the SH9's variation).
TEST(ResidualTruncation, ACubeOfTheSh9sIrradianceLeavesNothing) {
  const SphericalHarmonics9 sh = lopsidedSh9();
  const CubeMap cube =
      cubeFromRadiance(16, 1, [&](const glm::vec3& d) { return glm::max(sh.irradiance(d), glm::vec3(0.0f)); });
  const CubeMap truncation = residualTruncationCube(cube, sh);
  ASSERT_EQ(truncation.size, 16);
  float largest = 0.0f, range = 0.0f;
  for (const Image& face : truncation.faces)
    for (const glm::vec4& p : face.pixels()) {
      largest = std::max({largest, std::abs(p.r), std::abs(p.g), std::abs(p.b)});
      EXPECT_EQ(p.a, 1.0f);
    }
  for (const Image& face : cube.faces)
    for (const glm::vec4& p : face.pixels()) range = std::max(range, p.r);
  EXPECT_GT(range, 1.0f);
  EXPECT_LT(largest, 1e-5f * range);
}

// A constant cube minus a constant SH9 (band 0 only): the constants' difference everywhere, the
// negative part of it too (the correction may darken).
TEST(ResidualTruncation, ConstantsDifferEverywhereByTheirDifference) {
  CubeMap cube = cubeFromRadiance(4, 1, [](const glm::vec3&) { return glm::vec3(2.0f, 1.0f, 0.5f); });
  SphericalHarmonics9 sh;
  // E = pi Y_0 c_0 = pi 0.282095 c_0: c_0 = 1 / (pi 0.282095) gives E = 1.
  sh.coefficients[0] = glm::vec3(1.0f / (3.14159265f * 0.2820948f));
  const CubeMap truncation = residualTruncationCube(cube, sh);
  for (const Image& face : truncation.faces)
    for (const glm::vec4& p : face.pixels()) {
      EXPECT_NEAR(p.r, 1.0f, 1e-5f);
      EXPECT_NEAR(p.g, 0.0f, 1e-5f);
      EXPECT_NEAR(p.b, -0.5f, 1e-5f);
    }
  EXPECT_EQ(residualTruncationCube(CubeMap{}, sh).size, 0);
}

}  // namespace
}  // namespace iblkit
