#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "baker/specular_prefilter.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/low_discrepancy.h"
#include "core/microfacet.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// A sky gradient with a soft bright spot (peak 20x the sky): smooth, but varied enough that
// every roughness level differs from its neighbours.
EnvironmentMap softSpotEnvironment() {
  const glm::vec3 spot = glm::normalize(glm::vec3(0.6f, 0.5f, 0.3f));
  return EnvironmentMap::fromImage(
      latLongFromRadiance(
          512, 256, 2,
          [&](const glm::vec3& d) {
            const float t = 0.5f * (d.y + 1.0f);
            const glm::vec3 sky = glm::mix(glm::vec3(0.3f, 0.25f, 0.2f), glm::vec3(0.4f, 0.6f, 1.0f), t);
            return sky + glm::vec3(20.0f, 18.0f, 14.0f) * std::exp((glm::dot(d, spot) - 1.0f) / 0.05f);
          }),
      "soft-spot.exr");
}

// The GGX lobe around n (N = V = R) straight from the lat-long map: Hammersley samples of the
// NDF, bilinear lookups at full resolution, sum L NoL / sum NoL, no filtering.
glm::vec3 bruteForceLobe(const EnvironmentMap& environment, const glm::vec3& n, float roughness) {
  const float alpha = roughness * roughness, a2 = alpha * alpha;
  const Frame frame = Frame::fromZ(n);
  const std::uint32_t count = 16384;
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const glm::vec2 u = hammersley(i, count);
    const float cosThetaH = std::sqrt((1.0f - u.x) / (1.0f + (a2 - 1.0f) * u.x));
    const float sinThetaH = std::sqrt(1.0f - cosThetaH * cosThetaH);
    const float phi = 2.0f * glm::pi<float>() * u.y;
    const glm::vec3 h(sinThetaH * std::cos(phi), sinThetaH * std::sin(phi), cosThetaH);
    const glm::vec3 l = 2.0f * cosThetaH * h - glm::vec3(0.0f, 0.0f, 1.0f);
    if (l.z <= 0.0f) continue;
    sum += glm::dvec3(environment.radiance(frame.toWorld(l)) * l.z);
    weight += l.z;
  }
  return glm::vec3(sum / weight);
}

TEST(SpecularPrefilter, LevelsMatchABruteForceLobeIntegral) {
  const EnvironmentMap environment = softSpotEnvironment();
  const CubeMapLevels source = specularSourceChain(environment, 128);
  for (const float roughness : {0.25f, 0.5f, 0.75f, 1.0f}) {
    const int size = 4;  // 96 texels; every third one is compared.
    const CubeMap level =
        prefilterSpecularLevel(source, size, roughness, specularSampleCount(roughness, 1024));
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < 6 * size * size; i += 3, ++count) {
      const int face = i / (size * size), x = i % size, y = (i / size) % size;
      const glm::vec3 n = cubeDirection(face, (glm::vec2(x, y) + 0.5f) / static_cast<float>(size));
      const float exact = luminance(bruteForceLobe(environment, n, roughness));
      const float filtered = luminance(glm::vec3(level.faces[static_cast<std::size_t>(face)].at(x, y)));
      sum += std::abs(filtered - exact) / exact;
    }
    EXPECT_EQ(count, 32);
    std::printf("roughness %.2f: mean relative error %.2f%%\n", roughness, 100.0 * sum / count);
    EXPECT_LT(sum / count, 0.02) << "roughness " << roughness;
  }
}

TEST(SpecularPrefilter, SampleCountGrowsWithRoughness) {
  EXPECT_EQ(specularSampleCount(1.0f, 1024), 1024u);
  EXPECT_EQ(specularSampleCount(0.5f, 1024), 512u);
  EXPECT_EQ(specularSampleCount(0.05f, 1024), 64u);
  EXPECT_EQ(specularSampleCount(0.05f, 16), 16u);
}

TEST(SpecularPrefilter, LevelZeroIsTheRotatedScaledEnvironment) {
  EnvironmentMap environment = softSpotEnvironment();
  environment.setRotationDegrees(40.0f);
  environment.setIntensity(1.5f);
  const SpecularCube cube =
      prefilterSpecular(environment, {.baseSize = 16, .levelCount = 3, .sampleCount = 16});
  const CubeMap expected =
      cubeFromRadiance(16, 2, [&](const glm::vec3& d) { return environment.radiance(d); });
  ASSERT_EQ(cube.levels.size(), 3u);
  EXPECT_EQ(cube.roughness, (std::vector<float>{0.0f, 0.5f, 1.0f}));
  for (int face = 0; face < 6; ++face)
    EXPECT_EQ(cube.levels[0].faces[static_cast<std::size_t>(face)].pixels(),
              expected.faces[static_cast<std::size_t>(face)].pixels());
  EXPECT_EQ(cube.levels[1].size, 8);
  EXPECT_EQ(cube.levels[2].size, 4);
}

TEST(SpecularPrefilter, ConstantEnvironmentStaysConstantAtEveryLevel) {
  const SpecularCube cube = prefilterSpecular(EnvironmentMap::constant(glm::vec3(0.5f, 1.0f, 2.0f), 64));
  ASSERT_EQ(cube.levels.size(), 5u);  // base 16 -> 16, 8, 4, 2, 1
  EXPECT_FLOAT_EQ(cube.roughness[1], 0.25f);
  for (const CubeMap& level : cube.levels)
    for (const Image& face : level.faces)
      for (const glm::vec4& p : face.pixels()) {
        EXPECT_NEAR(p.r, 0.5f, 1e-5f);
        EXPECT_NEAR(p.g, 1.0f, 1e-5f);
        EXPECT_NEAR(p.b, 2.0f, 1e-5f);
      }
}

// Photographs come in any size (3000 x 1500, 6000 x 3000): the default base is the largest power
// of two at most width / 4, and a map whose width / 4 is not a power of two still prefilters. Large
// photographs (8192 and 16384 wide) stop at kMaxDefaultSpecularBaseSize.
TEST(SpecularPrefilter, AnyMapWidthGetsAPowerOfTwoBase) {
  EXPECT_EQ(defaultSpecularBaseSize(8), 2);
  EXPECT_EQ(defaultSpecularBaseSize(512), 128);
  EXPECT_EQ(defaultSpecularBaseSize(3000), 512);
  EXPECT_EQ(defaultSpecularBaseSize(6000), 1024);
  EXPECT_EQ(defaultSpecularBaseSize(8192), 1024);
  EXPECT_EQ(defaultSpecularBaseSize(16384), 1024);
  const SpecularCube cube = prefilterSpecular(EnvironmentMap::constant(glm::vec3(0.25f), 48));
  ASSERT_EQ(cube.levels.size(), 4u);  // 48 / 4 = 12 -> base 8 -> 8, 4, 2, 1
  EXPECT_EQ(cube.levels[0].size, 8);
  EXPECT_NEAR(cube.levels[3].faces[0].at(0, 0).r, 0.25f, 1e-5f);
}

TEST(SpecularPrefilter, RefusesBadChains) {
  const EnvironmentMap environment = EnvironmentMap::constant(glm::vec3(1.0f), 64);
  EXPECT_THROW(prefilterSpecular(environment, {.baseSize = 12}), std::invalid_argument);
  EXPECT_THROW(prefilterSpecular(environment, {.baseSize = 8, .levelCount = 5}), std::invalid_argument);
  EXPECT_THROW(prefilterSpecular(environment, {.baseSize = 8, .levelCount = 1}), std::invalid_argument);
  EXPECT_THROW(prefilterSpecularLevel(specularSourceChain(environment, 4), 2, 0.0f, 16),
               std::invalid_argument);
}

TEST(SpecularPrefilter, WritesAMipMappedCubeExr) {
  const SpecularCube cube = prefilterSpecular(softSpotEnvironment(), {.baseSize = 8, .sampleCount = 16});
  ASSERT_EQ(cube.levels.size(), 4u);
  const std::filesystem::path file = test::scratchDir() / "specular.exr";
  writeSpecularCubeExr(file, cube);
  ExrInfo info;
  const std::vector<Image> levels = readExrLevels(file, &info);
  EXPECT_EQ(info.envmap, EnvmapLayout::Cube);
  ASSERT_EQ(levels.size(), 6u);  // 8x48 ... 1x6, then OpenEXR's 1x3 and 1x1
  EXPECT_EQ(info.stringAttributes, (std::vector<std::pair<std::string, std::string>>{
                                       {"iblkit:roughnessPerLevel", "0 0.333333 0.666667 1"}}));
  for (std::size_t i = 0; i < cube.levels.size(); ++i)
    EXPECT_EQ(levels[i].pixels(), cubeToExrStrip(cube.levels[i]).pixels()) << "level " << i;
  EXPECT_EQ(levels[4].height(), 3);
  EXPECT_EQ(levels[5].height(), 1);
  glm::vec4 mean(0.0f);
  for (const glm::vec4& p : levels[3].pixels()) mean += p / 6.0f;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(levels[5].at(0, 0)[c], mean[c], 1e-5f * mean[c]);

  SpecularCube partial = cube;
  partial.levels.pop_back();
  partial.roughness.pop_back();
  EXPECT_EQ(test::errorMessage([&] { writeSpecularCubeExr("partial.exr", partial); }),
            "partial.exr: a specular cube of base size 8 needs the full chain down to 1 x 1, got 3 levels");
}

}  // namespace
}  // namespace iblkit
