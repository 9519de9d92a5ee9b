// env/irradiance.exr: the brute-force irradiance cube and the SH9 irradiance's error against it.
#include "baker/irradiance_cube.h"

#include "bakefile/irradiance_exr.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "bakefile/irradiance_exr.h"
#include "core/environment_sh.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

EnvironmentMap mapOf(int width, const std::function<glm::vec3(const glm::vec3&)>& radiance) {
  return EnvironmentMap::fromImage(latLongFromRadiance(width, width / 2, 2, radiance), "test map");
}

TEST(IrradianceCube, ConstantSkyGivesPiTimesItsRadianceEverywhere) {
  const CubeMap cube =
      irradianceCube(mapOf(64, [](const glm::vec3&) { return glm::vec3(0.5f, 1.0f, 2.0f); }), 4);
  ASSERT_EQ(cube.size, 4);
  for (const Image& face : cube.faces)
    for (const glm::vec4& p : face.pixels()) {
      EXPECT_NEAR(p.r, 0.5f * glm::pi<float>(), 5e-3f);
      EXPECT_NEAR(p.b, 2.0f * glm::pi<float>(), 2e-2f);
    }
}

// A sky of bands 0 and 1 only (L = 1 + 0.8 y): SH9 holds it exactly, so its irradiance matches
// the brute force up to the quadrature; a sharp sun does not fit in SH9 and shows a large error.
TEST(IrradianceCube, ShErrorIsSmallForALowFrequencySkyAndLargeForASun) {
  const EnvironmentMap smooth = mapOf(128, [](const glm::vec3& d) { return glm::vec3(1.0f + 0.8f * d.y); });
  const IrradianceError low = shIrradianceError(irradianceCube(smooth, 8), projectEnvironmentSh9(smooth));
  EXPECT_LT(low.meanRelative, 0.01f);
  EXPECT_LT(low.maxRelative, 0.03f);
  const EnvironmentMap sun = mapOf(128, [](const glm::vec3& d) {
    return glm::vec3(0.05f) +
           glm::vec3(200.0f) * glm::vec3(glm::dot(d, glm::normalize(glm::vec3(1, 1, 0))) > 0.99f);
  });
  const IrradianceError high = shIrradianceError(irradianceCube(sun, 8), projectEnvironmentSh9(sun));
  EXPECT_GT(high.maxRelative, 0.3f);
}

// Maps wider than kIrradianceSourceWidth are box-filtered first; even with a small bright sun the
// irradiance stays within 1% of the brute force over the full-resolution map.
TEST(IrradianceCube, WideMapsAreDownsampledFirst) {
  const glm::vec3 sun = glm::normalize(glm::vec3(1.0f, 0.7f, 0.3f));
  const auto sky = [&](const glm::vec3& d) {
    return glm::vec3(0.3f + 0.2f * d.y) + glm::vec3(1000.0f) * glm::vec3(glm::dot(d, sun) > 0.9976f);
  };
  const EnvironmentMap wide = mapOf(4 * kIrradianceSourceWidth, sky);
  const CubeMap fast = irradianceCube(wide, 4), exact = bruteForceIrradianceCube(wide, 4);
  for (int face = 0; face < 6; ++face)
    for (std::size_t i = 0; i < fast.faces[face].pixels().size(); ++i)
      EXPECT_NEAR(fast.faces[face].pixels()[i].g, exact.faces[face].pixels()[i].g,
                  0.01f * exact.faces[face].pixels()[i].g);
}

TEST(IrradianceCube, WritesAFloatCubeMapExr) {
  const CubeMap cube = irradianceCube(mapOf(32, [](const glm::vec3& d) { return glm::vec3(1.0f + d.z); }), 4);
  const std::filesystem::path file = test::scratchDir() / "irradiance.exr";
  writeIrradianceCubeExr(file, cube);
  ExrInfo info;
  const Image strip = readExr(file, &info);
  EXPECT_EQ(info.envmap, EnvmapLayout::Cube);
  EXPECT_EQ(strip.pixels(), cubeToExrStrip(cube).pixels());
  EXPECT_THROW(irradianceCube(mapOf(32, [](const glm::vec3&) { return glm::vec3(1.0f); }), 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
