// computeEnvironmentStages: the stages iblkit-bake writes and the viewer computes at run time.
#include "baker/environment_stages.h"

#include <gtest/gtest.h>

#include "core/environment_sh.h"
#include "support/bake_fixture.h"

namespace iblkit {
namespace {

TEST(EnvironmentStages, ViewerStagesAreTheBakersProjectionWindowedChainAndTable) {
  const EnvironmentMap sky = test::testSky();
  const EnvironmentStages stages =
      computeEnvironmentStages(
      sky, {.specularSamples = 16, .lutSize = 8, .lutSamples = 16, .irradianceCubeSize = 0});
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
  for (int k = 0; k < kShCoefficients; ++k)
    EXPECT_EQ(stages.sh9.coefficients[std::size_t(k)], stages.sh9Projection.coefficients[std::size_t(k)]);
  EXPECT_EQ(stages.irradiance.size, 4);
  EXPECT_GT(times.specular, 0.0);
  EXPECT_EQ(stages.rotationDegrees, sky.rotationDegrees());
}

}  // namespace
}  // namespace iblkit
