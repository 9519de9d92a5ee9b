// The sampling study on small images of the bundled bunny scene: the claim it measures (MIS at
// least 10x lower relMSE than cosine sampling on the sunny map, at equal spp), that every unbiased
// strategy converges to the MIS reference on the soft map (else the ratios would compare broken
// estimators), the point lights' aliasing on the sunny map (their error levels off at a bias that
// shrinks with more lights; median cut's unbiased sampler does not), the reference cache, and the
// settings it refuses.
#include "bench/env_sampling_study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/image_io.h"
#include "core/scene_environment.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

bool assetsFetched() { return fs::exists(test::assetsDir() / "hdri" / "sky.exr"); }

Scene bunny() { return loadScene(test::assetsDir() / "scenes" / "bunny.json"); }

// The map as the study program lights the bunny with it.
EnvironmentMap map(const std::string& name) {
  test::WarningCapture quiet;  // sky.exr has a few negative texels, repaired with a warning
  return loadSceneEnvironment(bunny(), test::assetsDir() / "hdri" / (name + ".exr"));
}

// 32 x 18 pixels, 1 to 64 spp against 1024 spp: about a second per map in a Release build.
SamplingStudySettings smallStudy() {
  SamplingStudySettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.maxSpp = 64;
  settings.referenceSpp = 1024;
  settings.cache = test::scratchDir() / "cache";
  return settings;
}

std::size_t levelOf(int spp, int maxSpp) {
  const std::vector<int> levels = studySppLevels(maxSpp);
  return static_cast<std::size_t>(std::find(levels.begin(), levels.end(), spp) - levels.begin());
}

void expectComplete(const MapStudy& study, std::size_t levels) {
  ASSERT_EQ(study.relMse.size(), kStudyStrategyCount);
  ASSERT_EQ(study.microsecondsPerSample.size(), kStudyStrategyCount);
  for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
    ASSERT_EQ(study.relMse[s].size(), levels) << kStudyStrategies[s].name;
    for (const double relMse : study.relMse[s]) EXPECT_TRUE(std::isfinite(relMse) && relMse > 0.0);
    EXPECT_GT(study.microsecondsPerSample[s], 0.0);
  }
}

TEST(EnvSamplingStudy, SunnyMapMisIsAtLeastTenTimesBetterThanCosineAtEqualSpp) {
  if (!assetsFetched()) GTEST_SKIP() << "assets not fetched";
  const SamplingStudySettings settings = smallStudy();
  const MapStudy sky = studyEnvironmentMap(settings, bunny(), map("sky"), "sky", "sunny");
  expectComplete(sky, 7);
  EXPECT_FALSE(sky.referenceCached);
  // Measured at 32 x 18 (relMSE cosine / mis): 109 / 0.00793 = 13,700x at 32 spp and
  // 28.1 / 0.0034 = 8,300x at 64 spp; at least 84x over sizes 24 x 14 to 48 x 27. Cosine's error is
  // made of the rare samples that find the sun; where it found none (48 x 27 at 32 spp, 24 x 14 up
  // to 8 spp) its relMSE is that of a sunless image, 0.39 to 0.65, which is still 50x MIS's 0.008
  // at 32 spp and 110x its 0.0035 at 64. Below 32 spp the claim does not hold at this size: MIS has
  // not converged enough (0.91 at 1 spp, 0.019 at 16) to be 10x below a sunless cosine render.
  // With the environment sampler blind to luminance (texel weights by solid angle alone: unbiased,
  // but it misses the sun like cosine does) the ratio falls to 5.8x at 32 spp and 0.8x at 64.
  for (const int spp : {32, 64}) {
    const double ratio =
        relMseRatio(sky, EnvSampling::Cosine, EnvSampling::Mis, levelOf(spp, settings.maxSpp));
    EXPECT_GE(ratio, 10.0) << spp << " spp";
    RecordProperty("cosine_over_mis_" + std::to_string(spp) + "spp", std::to_string(ratio));
  }
  // MIS converges (0.91 at 1 spp to 0.0034 at 64, 270x), and the reference is good enough to
  // measure it: its own noise (7.9e-4) is below MIS's error at 64 spp.
  const std::vector<double>& mis = sky.relMse[studyStrategyIndex(EnvSampling::Mis)];
  EXPECT_LT(mis.back(), mis.front() / 20.0);
  EXPECT_GT(sky.referenceFloor, 0.0);
  EXPECT_LT(sky.referenceFloor, mis.back());
}

TEST(EnvSamplingStudy, SoftMapEveryStrategyConvergesToTheMisReference) {
  if (!assetsFetched()) GTEST_SKIP() << "assets not fetched";
  const SamplingStudySettings settings = smallStudy();
  const MapStudy venice = studyEnvironmentMap(settings, bunny(), map("venice"), "venice", "soft");
  expectComplete(venice, 7);
  // Without peaks every strategy is a usable estimator of the same image. Measured at 32 x 18, each
  // one's relMSE falls 31x (uniform, cosine) to 35x (brdf, env) from 4 to 64 spp; 20.6x (brdf at
  // 24 x 14) to 40x over sizes 24 x 14 to 48 x 27. A strategy that converges to another image than
  // the reference levels off instead: with the environment sampler's pdf doubled in sample() alone,
  // env only goes from 0.155 at 4 spp to 0.136 at 64. (A MIS bias of a few percent, which moves the
  // reference too, is below what this sees; tests/reference/integrator_test.cpp holds MIS to 1%.)
  for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
    if (kStudyStrategies[s].sampling == EnvSampling::Lights) continue;  // biased (the next test)
    const std::vector<double>& relMse = venice.relMse[s];
    EXPECT_LT(relMse[levelOf(64, settings.maxSpp)], relMse[levelOf(4, settings.maxSpp)] / 8.0)
        << kStudyStrategies[s].name;
  }
}

TEST(EnvSamplingStudy, SunnyMapPointLightsLevelOffAtTheirBiasAndMedianCutSamplingDoesNot) {
  if (!assetsFetched()) GTEST_SKIP() << "assets not fetched";
  const SamplingStudySettings settings = smallStudy();
  const MapStudy sky = studyEnvironmentMap(settings, bunny(), map("sky"), "sky", "sunny");
  const std::size_t at4 = levelOf(4, settings.maxSpp), at16 = levelOf(16, settings.maxSpp),
                    at64 = levelOf(64, settings.maxSpp);
  const auto relMse = [&](const char* name, std::size_t level) {
    return sky.relMse[studyStrategyIndex(name)][level];
  };
  for (const char* name : {"lights4", "lights16", "lights64", "lights256", "mis", "mediancut"})
    RecordProperty(std::string(name) + "_64spp", std::to_string(relMse(name, at64)));
  // Measured at 32 x 18 against 1024 spp (relMSE at 16 and 64 spp): lights4 levels off at its bias,
  // from 16 to 64 spp its error falls by less than the 4x of an unbiased estimator's; with more
  // lights the bias is lower (lights256 0.0015 against lights4 0.0071 at 64 spp). Their variance is
  // low (no sky noise), so at this size and spp they stay below mis (0.0030) except lights4.
  EXPECT_GT(relMse("lights4", at64), relMse("lights4", at16) / 2.0);
  EXPECT_GT(relMse("lights4", at64), 2.0 * relMse("lights256", at64));
  // Median-cut sampling is unbiased: it converges like mis and env.
  EXPECT_LT(relMse("mediancut", at64), relMse("mediancut", at4) / 8.0);
  EXPECT_LT(relMse("mediancut", at64), 3.0 * relMse("env", at64));
}

TEST(EnvSamplingStudy, SecondRunReadsTheCachedReference) {
  if (!assetsFetched()) GTEST_SKIP() << "assets not fetched";
  SamplingStudySettings settings = smallStudy();
  settings.width = 16;
  settings.height = 9;
  settings.maxSpp = 4;
  settings.referenceSpp = 16;
  std::vector<std::string> log;
  const auto record = [&log](const std::string& line) { log.push_back(line); };
  const MapStudy first = studyEnvironmentMap(settings, bunny(), map("sky"), "sky", "sunny", record);
  const MapStudy second = studyEnvironmentMap(settings, bunny(), map("sky"), "sky", "sunny", record);
  EXPECT_FALSE(first.referenceCached);
  EXPECT_TRUE(second.referenceCached);
  EXPECT_EQ(second.relMse, first.relMse);  // the renders are deterministic and the cache is float
  EXPECT_EQ(second.referenceFloor, first.referenceFloor);
  // One reference line, then a line per strategy per run.
  ASSERT_EQ(log.size(), 1 + 2 * kStudyStrategyCount);
  EXPECT_EQ(log[0], "sky: rendering the reference, 16 spp mis");
  EXPECT_EQ(log[1].rfind("sky uniform relMSE ", 0), 0u) << log[1];

  // A cached reference of another size (the key said otherwise: the files were replaced) is refused.
  int replaced = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(settings.cache)) {
    writeExr(entry.path(), Image(4, 4));
    ++replaced;
  }
  EXPECT_EQ(replaced, 2);  // the beauty and its variance
  const std::string error =
      test::errorMessage([&] { studyEnvironmentMap(settings, bunny(), map("sky"), "sky", "sunny"); });
  EXPECT_NE(error.find("cached reference has the wrong size"), std::string::npos) << error;
}

TEST(EnvSamplingStudy, SppLevelsArePowersOfTwoUpToTheMaximum) {
  EXPECT_EQ(studySppLevels(1), std::vector<int>({1}));
  EXPECT_EQ(studySppLevels(64), std::vector<int>({1, 2, 4, 8, 16, 32, 64}));
  EXPECT_EQ(studySppLevels(48), std::vector<int>({1, 2, 4, 8, 16, 32}));
  EXPECT_TRUE(studySppLevels(0).empty());
  const std::vector<int> all = studySppLevels(INT_MAX);  // stops at 2^30 instead of overflowing
  ASSERT_EQ(all.size(), 31u);
  EXPECT_EQ(all.back(), 1 << 30);
}

TEST(EnvSamplingStudy, ReferenceNoiseFloorIsTheMeanRelativeVariance) {
  // variance / (reference^2 + 0.01) is 0.01 in every channel of both pixels.
  Image reference(2, 1, glm::vec4(1.0f)), variance(2, 1, glm::vec4(0.0101f));
  reference.at(1, 0) = glm::vec4(0.0f);
  variance.at(1, 0) = glm::vec4(0.0001f);
  EXPECT_NEAR(referenceNoiseFloor(reference, variance), 0.01, 1e-8);
}

TEST(EnvSamplingStudy, BadSettingsAreRefusedNamingTheOption) {
  const auto refused = [](const auto& change) {
    SamplingStudySettings settings;
    change(settings);
    return test::errorMessage([&] { validateSamplingStudySettings(settings); });
  };
  EXPECT_EQ(refused([](SamplingStudySettings&) {}), "(no error)");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.width = 0; }), "--width: must be in 1..16384, not 0");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.height = 16385; }),
            "--height: must be in 1..16384, not 16385");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.maxSpp = -4; }),
            "--max-spp: must be in 1..16777216, not -4");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.referenceSpp = INT_MAX; }),
            "--reference-spp: must be in 1..16777216, not 2147483647");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.threads = -1; }), "--threads: must be >= 0, not -1");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.phong = -1.0f; }),
            "--phong: exponent must be finite and >= 0");
  EXPECT_EQ(refused([](SamplingStudySettings& s) { s.phong = NAN; }),
            "--phong: exponent must be finite and >= 0");
}

}  // namespace
}  // namespace iblkit
