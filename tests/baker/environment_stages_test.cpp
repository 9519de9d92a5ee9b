// computeEnvironmentStages: the stages iblkit-bake writes and the viewer computes at run time,
// the dominant lights and the residual's SH9 and chain included.
#include "baker/environment_stages.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <utility>

#include "bakefile/bake_layout.h"
#include "core/environment_lights.h"
#include "core/environment_sh.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "support/bake_fixture.h"
#include "support/error_capture.h"
#include "support/sun_map.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

TEST(EnvironmentStages, ViewerStagesAreTheBakersProjectionWindowedChainAndTable) {
  const EnvironmentMap sky = test::testSky();
  const EnvironmentStages stages =
      computeEnvironmentStages(
      sky, {.shWindowCutoff = std::nullopt, .specularSamples = 16, .lutSize = 8, .lutSamples = 16, .irradianceCubeSize = 0});
  EXPECT_EQ(stages.latLong.width(), 64);
  EXPECT_EQ(stages.specular.levels.front().size, 16);  // width / 4
  EXPECT_EQ(stages.specular.levels.back().size, 1);
  EXPECT_EQ(stages.brdfLut.width(), 8);
  // The SH9 stage is the baker's projection with its automatic ringing window.
  const SphericalHarmonics9 projected = projectEnvironmentSh9(sky);
  // (Equal up to the order of TBB's parallel sums.)
  EXPECT_NEAR(stages.shWindowCutoff, automaticShWindowCutoff(projected), 1e-3f);
  const SphericalHarmonics9 windowed = windowSh9(projected, stages.shWindowCutoff);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(stages.sh9.coefficients[std::size_t(k)][c], windowed.coefficients[std::size_t(k)][c], 1e-5f);
}

TEST(EnvironmentStages, FixedWindowIrradianceCubeProgressAndTimes) {
  const EnvironmentMap sky = test::testSky();
  std::vector<std::size_t> steps;
  EnvironmentStageTimes times;
  const EnvironmentStages stages = computeEnvironmentStages(
      sky, {.shWindowCutoff = 0.0f, .specularSamples = 16, .lutSize = 8, .lutSamples = 16, .irradianceCubeSize = 4},
      [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 4u);
        steps.push_back(done);
      },
      &times);
  EXPECT_EQ(steps, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(stages.shWindowCutoff, 0.0f);
  EXPECT_EQ(stages.sh9.coefficients, projectEnvironmentSh9(sky).coefficients);
  EXPECT_EQ(stages.irradiance.size, 4);
  EXPECT_GT(times.specular, 0.0);
  EXPECT_EQ(stages.rotationDegrees, sky.rotationDegrees());
}

// A map with a small bright sun rings in SH9, so the automatic window is on; the bake folder must
// hold the windowed coefficients the in-memory stages use (docs/prefilter.md), not the projection.
TEST(EnvironmentStages, TheBakeFolderHoldsTheWindowedCoefficientsTheEngineUses) {
  const EnvironmentMap sunny = EnvironmentMap::fromImage(
      latLongFromRadiance(64, 32, 2,
                          [](const glm::vec3& d) {
                            return glm::vec3(0.2f) + glm::vec3(5000.0f) * std::pow(std::max(0.0f, d.y), 400.0f);
                          }),
      "sunny");
  const EnvironmentStages stages = computeEnvironmentStages(
      sunny, {.shWindowCutoff = std::nullopt, .specularSamples = 16, .lutSize = 8, .lutSamples = 16, .irradianceCubeSize = 0});
  ASSERT_GT(stages.shWindowCutoff, 0.0f);
  const SphericalHarmonics9 projection = projectEnvironmentSh9(sunny);
  EXPECT_NE(stages.sh9.coefficients, projection.coefficients);
  const fs::path folder = test::scratchDir() / "windowed_stages";
  fs::remove_all(folder);
  writeEnvironmentStages(folder, stages);
  writeExr(folder / "sunny.exr", stages.latLong, {.pixelType = PixelType::Float});
  BakeInputs inputs;
  inputs.environment = folder / "sunny.exr";
  const EnvironmentStages read = readEnvironmentStages(folder, inputs);
  EXPECT_EQ(read.shWindowCutoff, stages.shWindowCutoff);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_FLOAT_EQ(read.sh9.coefficients[std::size_t(k)][c], stages.sh9.coefficients[std::size_t(k)][c]) << k;
}

// A 64 x 32 sky with one sun 6 degrees wide (a few texels), for quick stages.
EnvironmentMap quickSunnySky() {
  EnvironmentMap map =
      test::sunnySky(64, {test::SunDisk{.direction = glm::normalize(glm::vec3(0.5f, 0.7f, 0.3f)),
                                        .angularRadius = 0.1f,
                                        .radiance = glm::vec3(400.0f, 350.0f, 300.0f)}});
  map.setRotationDegrees(35.0f);
  map.setIntensity(1.5f);
  return map;
}

constexpr EnvironmentStageOptions kQuickLightStages{.shWindowCutoff = std::nullopt,
                                                    .specularSamples = 16,
                                                    .lutSize = 8,
                                                    .lutSamples = 16,
                                                    .irradianceCubeSize = 0,
                                                    .lights = true};

TEST(EnvironmentStages, LightsAreTheSunsAndMedianCutAndTheResidualHasItsOwnShAndChain) {
  const EnvironmentMap map = quickSunnySky();
  std::vector<std::size_t> steps;
  EnvironmentStageTimes times;
  const EnvironmentStages stages = computeEnvironmentStages(
      map, kQuickLightStages,
      [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 6u);
        steps.push_back(done);
      },
      &times);
  EXPECT_EQ(steps, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_GT(times.residualSpecular, 0.0);
  const ExtractedSuns extracted = extractSuns(map);
  ASSERT_EQ(stages.lights.suns.size(), 1u);
  EXPECT_EQ(stages.lights.suns[0].irradiance, extracted.suns[0].irradiance);
  EXPECT_EQ(stages.lights.suns[0].direction, extracted.suns[0].direction);
  EXPECT_EQ(stages.lights.sunThreshold, extracted.threshold);
  EXPECT_EQ(stages.lights.medianCutLevels, kDefaultMedianCutLevels);
  EXPECT_EQ(stages.lights.medianCut.size(), medianCutLights(map, kDefaultMedianCutLevels).size());
  // The residual, in the map's frame, with the map's window.
  EnvironmentMap residual = EnvironmentMap::fromImage(extracted.residual, "residual");
  residual.setRotationDegrees(map.rotationDegrees());
  residual.setIntensity(map.intensity());
  const SphericalHarmonics9 residualSh = windowSh9(projectEnvironmentSh9(residual), stages.shWindowCutoff);
  // Windowing is linear: the residual's windowed SH9 plus the sun's is the map's (sh9).
  const SphericalHarmonics9 sunSh = windowSh9(stages.lights.suns[0].sh9, stages.shWindowCutoff);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(stages.residualSh9.coefficients[k][c], residualSh.coefficients[k][c],
                  1e-5f * stages.sh9.coefficients[0][c]);
      EXPECT_NEAR(stages.residualSh9.coefficients[k][c] + sunSh.coefficients[k][c],
                  stages.sh9.coefficients[k][c], 1e-5f * stages.sh9.coefficients[0][c]);
    }
  // The residual's chain is the prefiltered residual: same sizes and roughness, and its level 0
  // in the sun's direction holds at most the threshold's luminance (bilinear between texels at or
  // below it), far below the map's.
  ASSERT_EQ(stages.residualSpecular.levels.size(), stages.specular.levels.size());
  EXPECT_EQ(stages.residualSpecular.roughness, stages.specular.roughness);
  const glm::vec3 sun = stages.lights.suns[0].direction;
  const float residualAtSun = luminance(sampleCubeBilinear(stages.residualSpecular.levels[0], sun));
  const float mapAtSun = luminance(sampleCubeBilinear(stages.specular.levels[0], sun));
  EXPECT_LE(residualAtSun, stages.lights.sunThreshold * 1.001f);
  EXPECT_GT(mapAtSun, 3.0f * residualAtSun);
}

// From a map the caller is done with (iblkit-bake's), the residual is the map's own image with the
// suns' texels replaced, not a copy: the same stages, bit for bit, and the map left empty. The
// extraction's list of the replaced texels is the difference between the map and its residual.
TEST(EnvironmentStages, AMovedMapBecomesTheResidualInPlaceWithTheSameStages) {
  EnvironmentMap map = quickSunnySky();
  map.setRotationDegrees(23.0f);
  const EnvironmentStages copied = computeEnvironmentStages(map, kQuickLightStages);
  EnvironmentMap moved = map;
  const EnvironmentStages inPlace = computeEnvironmentStages(std::move(moved), kQuickLightStages);
  EXPECT_TRUE(moved.image().empty());
  EXPECT_EQ(inPlace.residualSh9.coefficients, copied.residualSh9.coefficients);
  EXPECT_EQ(inPlace.sh9.coefficients, copied.sh9.coefficients);
  ASSERT_EQ(inPlace.residualSpecular.levels.size(), copied.residualSpecular.levels.size());
  for (std::size_t level = 0; level < copied.residualSpecular.levels.size(); ++level)
    for (int face = 0; face < 6; ++face)
      EXPECT_EQ(inPlace.residualSpecular.levels[level].faces[std::size_t(face)].pixels(),
                copied.residualSpecular.levels[level].faces[std::size_t(face)].pixels())
          << "level " << level << ", face " << face;
  EXPECT_EQ(inPlace.residualIrradiance.faces[0].pixels(), copied.residualIrradiance.faces[0].pixels());
  ASSERT_EQ(inPlace.lights.suns.size(), 1u);
  EXPECT_EQ(inPlace.lights.suns[0].irradiance, copied.lights.suns[0].irradiance);
  // The replaced texels: where the map and its residual differ, and nowhere else.
  const ExtractedSuns extracted = extractSuns(map);
  ASSERT_FALSE(extracted.residualTexels.empty());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < map.image().pixels().size(); ++i)
    differing += map.image().pixels()[i] != extracted.residual.pixels()[i];
  EXPECT_EQ(differing, extracted.residualTexels.size());
  for (const auto& [texel, value] : extracted.residualTexels) EXPECT_EQ(extracted.residual.pixels()[texel], value);
  SunExtractionOptions noImage;
  noImage.residualImage = false;
  const ExtractedSuns texelsOnly = extractSuns(map, noImage);
  EXPECT_TRUE(texelsOnly.residual.empty());
  EXPECT_EQ(texelsOnly.residualTexels, extracted.residualTexels);
}

TEST(EnvironmentStages, TheBakeFolderHoldsTheLightsAndTheResidual) {
  const EnvironmentMap map = quickSunnySky();
  const EnvironmentStages stages = computeEnvironmentStages(map, kQuickLightStages);
  const fs::path scratch = test::scratchDir(), folder = scratch / "light_stages";
  writeEnvironmentStages(folder, stages);
  writeExr(folder / "sunny.exr", stages.latLong, {.pixelType = PixelType::Float});
  BakeInputs inputs;
  inputs.environment = folder / "sunny.exr";
  inputs.environmentRotationDegrees = map.rotationDegrees();
  inputs.environmentIntensity = map.intensity();
  const EnvironmentStages read = readEnvironmentStages(folder, inputs);
  ASSERT_EQ(read.lights.suns.size(), stages.lights.suns.size());
  EXPECT_EQ(read.lights.suns[0].irradiance, stages.lights.suns[0].irradiance);
  EXPECT_EQ(read.lights.suns[0].sh9.coefficients, stages.lights.suns[0].sh9.coefficients);
  EXPECT_EQ(read.lights.medianCut.size(), stages.lights.medianCut.size());
  EXPECT_EQ(read.lights.sunThreshold, stages.lights.sunThreshold);
  EXPECT_EQ(read.residualSh9.coefficients, stages.residualSh9.coefficients);
  ASSERT_EQ(read.residualSpecular.levels.size(), stages.residualSpecular.levels.size());
  EXPECT_EQ(read.residualSpecular.levels[1].faces[2].pixels(),
            stages.residualSpecular.levels[1].faces[2].pixels());
  // The residual's files come with env/lights.json.
  fs::remove(folder / kBakeResidualSpecularFile);
  EXPECT_EQ(test::errorMessage([&] { readEnvironmentStages(folder, inputs); }),
            (folder / kBakeResidualSpecularFile).string() + ": missing (incomplete bake folder?)");
  // A bake without lights (stages computed without them) has none, and reads so.
  const fs::path plain = scratch / "plain_stages";
  writeEnvironmentStages(plain, computeEnvironmentStages(map, {.shWindowCutoff = std::nullopt,
                                                               .specularSamples = 16,
                                                               .lutSize = 8,
                                                               .lutSamples = 16,
                                                               .irradianceCubeSize = 0}));
  EXPECT_FALSE(fs::exists(plain / kBakeLightsFile));
  const EnvironmentStages none = readEnvironmentStages(plain, inputs);
  EXPECT_TRUE(none.lights.suns.empty());
  EXPECT_TRUE(none.lights.medianCut.empty());
  EXPECT_TRUE(none.residualSpecular.levels.empty());
}

}  // namespace
}  // namespace iblkit
