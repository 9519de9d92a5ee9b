// computeEnvironmentStages: the stages iblkit-bake writes and the viewer computes at run time.
#include "baker/environment_stages.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/environment_sh.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "support/bake_fixture.h"
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

}  // namespace
}  // namespace iblkit
