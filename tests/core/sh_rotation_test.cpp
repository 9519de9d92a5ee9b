#include "core/sh_rotation.h"

#include <gtest/gtest.h>

#include "core/environment_sh.h"
#include "core/environment_map.h"

namespace iblkit {
namespace {

SphericalHarmonics9 someSh() {
  SphericalHarmonics9 sh;
  for (int k = 0; k < kShCoefficients; ++k)
    sh.coefficients[std::size_t(k)] =
        glm::vec3(0.3f + 0.1f * float(k), -0.2f + 0.05f * float(k * k % 7), 0.7f - 0.08f * float(k));
  return sh;
}

// The rotated coefficients reproduce the function turned as EnvironmentMap turns the map:
// rotated(d) = sh(R_y(-angle) d), checked with EnvironmentMap::toMapDirection.
TEST(ShRotation, MatchesTheEnvironmentMapRotationConvention) {
  const SphericalHarmonics9 sh = someSh();
  for (float degrees : {90.0f, -37.5f, 200.0f}) {
    const SphericalHarmonics9 rotated = rotateShAboutY(sh, degrees);
    EnvironmentMap frame = EnvironmentMap::constant(glm::vec3(1.0f));
    frame.setRotationDegrees(degrees);
    for (const glm::vec3& d : fibonacciSphere(100)) {
      const glm::vec3 expected = sh.evaluate(frame.toMapDirection(d));
      const glm::vec3 got = rotated.evaluate(d);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-5f) << degrees;
    }
  }
}

TEST(ShRotation, ZeroAndFullTurnsAreTheIdentityAndBandZeroNeverMoves) {
  const SphericalHarmonics9 sh = someSh();
  for (float degrees : {0.0f, 360.0f}) {
    const SphericalHarmonics9 rotated = rotateShAboutY(sh, degrees);
    for (int k = 0; k < kShCoefficients; ++k)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rotated.coefficients[std::size_t(k)][c], sh.coefficients[std::size_t(k)][c], 2e-5f);
  }
  // Y_1,-1 is proportional to y, which a turn about +Y keeps.
  const SphericalHarmonics9 turned = rotateShAboutY(sh, 123.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(turned.coefficients[0][c], sh.coefficients[0][c], 1e-5f);
    EXPECT_NEAR(turned.coefficients[1][c], sh.coefficients[1][c], 1e-5f);
  }
}

}  // namespace
}  // namespace iblkit
