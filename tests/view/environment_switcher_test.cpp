// Environment switching without a window: the folder's maps are listed, a request is prefiltered
// on the worker thread with the scene's rotation and intensity, a broken map leaves the current
// environment, and stepping wraps around.
#include "engine/view/environment_switcher.h"

#include <gtest/gtest.h>

#include <fstream>

#include "baker/environment_stages.h"
#include "core/image_io.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

EnvironmentStages prepareSmall(const EnvironmentMap& map) {
  return computeEnvironmentStages(map,
                                  {.shWindowCutoff = std::nullopt, .specularSamples = 16, .lutSize = 8, .lutSamples = 16, .irradianceCubeSize = 0});
}

void writeConstantMap(const fs::path& file, const glm::vec3& radiance) {
  writeExr(file, Image(32, 16, glm::vec4(radiance, 1.0f)), {.pixelType = PixelType::Float});
}

// The folder: a red and a blue constant map, a broken .exr, and a file that is no map.
fs::path makeFolder() {
  const fs::path dir = test::scratchDir();
  writeConstantMap(dir / "b_red.exr", glm::vec3(1.0f, 0.0f, 0.0f));
  writeConstantMap(dir / "a_blue.EXR", glm::vec3(0.0f, 0.0f, 1.0f));
  std::ofstream(dir / "c_broken.exr") << "not an OpenEXR file";
  std::ofstream(dir / "notes.txt") << "not a map";
  return dir;
}

TEST(EnvironmentSwitcher, ListsTheMapsOfTheFolderSorted) {
  const fs::path dir = makeFolder();
  const EnvironmentSwitcher switcher(dir, 0.0f, 1.0f, prepareSmall);
  ASSERT_EQ(switcher.files().size(), 3u);
  EXPECT_EQ(switcher.files()[0].filename(), "a_blue.EXR");
  EXPECT_EQ(switcher.files()[1].filename(), "b_red.exr");
  EXPECT_EQ(switcher.files()[2].filename(), "c_broken.exr");
  EXPECT_EQ(switcher.current(), -1);
  EXPECT_FALSE(switcher.busy());

  const EnvironmentSwitcher missing(dir / "nowhere", 0.0f, 1.0f, prepareSmall);
  EXPECT_TRUE(missing.files().empty());
  EXPECT_NE(missing.status().find("nowhere"), std::string::npos) << missing.status();
}

TEST(EnvironmentSwitcher, PrefiltersARequestOnTheWorkerWithTheScenesIntensity) {
  const fs::path dir = makeFolder();
  EnvironmentSwitcher switcher(dir, 30.0f, 2.0f, prepareSmall);
  switcher.request(1);  // b_red.exr
  EXPECT_TRUE(switcher.busy());
  EXPECT_EQ(switcher.pending(), 1);
  EXPECT_NE(switcher.status().find("prefiltering b_red.exr"), std::string::npos) << switcher.status();
  const std::optional<EnvironmentStages> stages = switcher.waitForResult();
  ASSERT_TRUE(stages.has_value());
  EXPECT_EQ(switcher.current(), 1);
  EXPECT_FALSE(switcher.busy());
  EXPECT_EQ(switcher.status(), "b_red.exr");
  EXPECT_EQ(stages->rotationDegrees, 30.0f);
  EXPECT_EQ(stages->intensity, 2.0f);
  // A constant radiance c has L_00 = c * 4 pi Y_00 = c * 2 sqrt(pi) (the window keeps band 0).
  const glm::vec3 l00 = stages->sh9.coefficients[0];
  EXPECT_NEAR(l00.r, 2.0f * 2.0f * std::sqrt(glm::pi<float>()), 0.02f);
  EXPECT_NEAR(l00.b, 0.0f, 1e-4f);
  EXPECT_FALSE(stages->specular.levels.empty());
  EXPECT_EQ(stages->brdfLut.width(), 8);
  EXPECT_FALSE(switcher.poll().has_value());  // delivered once
}

TEST(EnvironmentSwitcher, ABrokenMapKeepsTheCurrentEnvironmentAndSaysWhy) {
  const fs::path dir = makeFolder();
  EnvironmentSwitcher switcher(dir, 0.0f, 1.0f, prepareSmall);
  switcher.request(0);
  ASSERT_TRUE(switcher.waitForResult().has_value());
  switcher.request(2);
  EXPECT_FALSE(switcher.waitForResult().has_value());
  EXPECT_EQ(switcher.current(), 0);
  EXPECT_NE(switcher.status().find("c_broken.exr"), std::string::npos) << switcher.status();
  switcher.request(7);  // out of range: ignored
  EXPECT_FALSE(switcher.busy());
}

TEST(EnvironmentSwitcher, StepsWrapAroundAndTheLatestQueuedRequestWins) {
  const fs::path dir = makeFolder();
  EnvironmentSwitcher switcher(dir, 0.0f, 1.0f, prepareSmall);
  switcher.step(-1);  // from the bake's: the last file (the broken one: nothing changes)
  EXPECT_EQ(switcher.pending(), 2);
  EXPECT_FALSE(switcher.waitForResult().has_value());
  switcher.step(+1);  // still the bake's: the first file
  EXPECT_EQ(switcher.pending(), 0);
  switcher.request(2);  // queued behind 0
  switcher.request(1);  // replaces it
  const std::optional<EnvironmentStages> last = switcher.waitForResult();
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(switcher.current(), 1);
  EXPECT_GT(last->sh9.coefficients[0].r, 1.0f);  // b_red
}

}  // namespace
}  // namespace iblkit
