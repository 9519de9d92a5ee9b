#include "core/scene_environment.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/image_io.h"
#include "core/usage_error.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// A scene whose environment is `file` at 30 degrees and intensity 2.
Scene sceneLitBy(const fs::path& file) {
  Scene scene;
  scene.file = "scene.json";
  scene.environment = {.file = file, .rotationDegrees = 30.0f, .intensity = 2.0f};
  return scene;
}

EnvironmentOverride override(std::optional<float> rotationDegrees, std::optional<float> intensity) {
  EnvironmentOverride made;
  made.rotationDegrees = rotationDegrees;
  made.intensity = intensity;
  return made;
}

TEST(SceneEnvironment, TheScenesSettingsUnlessOverridden) {
  const fs::path dir = test::scratchDir();
  writeExr(dir / "a.exr", Image(16, 8, glm::vec4(1.0f)));
  writeExr(dir / "b.exr", Image(16, 8, glm::vec4(3.0f)));
  const Scene scene = sceneLitBy(dir / "a.exr");

  const EnvironmentMap plain = loadSceneEnvironment(scene);
  EXPECT_EQ(plain.rotationDegrees(), 30.0f);
  EXPECT_EQ(plain.intensity(), 2.0f);
  EXPECT_EQ(plain.image().at(0, 0).r, 1.0f);

  // Each override replaces its own setting only; the rotation is absolute, not added.
  const EnvironmentMap rotated = loadSceneEnvironment(scene, override(90.0f, std::nullopt));
  EXPECT_EQ(rotated.rotationDegrees(), 90.0f);
  EXPECT_EQ(rotated.intensity(), 2.0f);
  EnvironmentOverride otherMap = override(std::nullopt, 0.5f);
  otherMap.file = dir / "b.exr";
  const EnvironmentMap other = loadSceneEnvironment(scene, otherMap);
  EXPECT_EQ(other.rotationDegrees(), 30.0f);
  EXPECT_EQ(other.intensity(), 0.5f);
  EXPECT_EQ(other.image().at(0, 0).r, 3.0f);
}

TEST(SceneEnvironment, ASceneWithoutAMapNeedsAnOverride) {
  const fs::path dir = test::scratchDir();
  writeExr(dir / "a.exr", Image(16, 8, glm::vec4(1.0f)));
  const Scene bare = sceneLitBy("");
  EXPECT_EQ(test::errorMessage([&] { loadSceneEnvironment(bare); }),
            "scene.json: the scene names no environment map (give --env FILE)");
  EXPECT_EQ(overriddenEnvironment(bare.environment, EnvironmentOverride()).file, fs::path());
  EXPECT_EQ(loadSceneEnvironment(bare, dir / "a.exr").rotationDegrees(), 30.0f);
}

TEST(SceneEnvironment, OverridesNoMapCanTakeAreUsageErrors) {
  const auto usageMessage = [](const EnvironmentOverride& override) {
    try {
      checkEnvironmentOverride(override);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("(no usage error)");
  };
  EXPECT_EQ(usageMessage(override(-720.0f, 0.0f)), "(no usage error)");
  EXPECT_EQ(usageMessage(override(std::numeric_limits<float>::infinity(), std::nullopt)),
            "--env-rotation: must be finite");
  EXPECT_EQ(usageMessage(override(std::nullopt, -1.0f)), "--env-intensity: must be finite and >= 0");
  EXPECT_EQ(usageMessage(override(std::nullopt, std::numeric_limits<float>::quiet_NaN())),
            "--env-intensity: must be finite and >= 0");
}

}  // namespace
}  // namespace iblkit
