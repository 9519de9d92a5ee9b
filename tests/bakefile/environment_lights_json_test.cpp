// env/lights.json: what is written reads back to the last bit; bad files are one-line errors
// naming the file and the entry; the writer refuses non-finite values and leaves no file.
#include "bakefile/environment_lights_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

EnvironmentLight testLight(EnvironmentLightKind kind, float seed) {
  EnvironmentLight light;
  light.kind = kind;
  light.direction = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f + seed));
  light.irradiance = glm::vec3(1.0f / 3.0f, 2.5f, 1e-7f) * (1.0f + seed);
  light.solidAngle = 6.8e-4f * (1.0f + seed);
  light.angularRadius = std::acos(1.0f - light.solidAngle / (2.0f * 3.14159265f));
  light.radiance = light.irradiance / light.solidAngle;
  light.x0 = 299;
  light.y0 = 55;
  light.x1 = 515;  // wraps past a width of 512
  light.y1 = 64;
  for (int k = 0; k < kShCoefficients; ++k)
    light.sh9.coefficients[std::size_t(k)] = glm::vec3(0.1f * float(k) - 0.37f, seed, -1.0f / float(k + 1));
  return light;
}

EnvironmentLights testLights() {
  EnvironmentLights lights;
  lights.suns = {testLight(EnvironmentLightKind::Sun, 0.0f), testLight(EnvironmentLightKind::Sun, 0.25f)};
  lights.sunThreshold = 21.8270741f;
  lights.medianCut = {testLight(EnvironmentLightKind::MedianCut, 0.5f)};
  lights.medianCutLevels = 4;
  return lights;
}

void expectSameLight(const EnvironmentLight& a, const EnvironmentLight& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.irradiance, b.irradiance);
  EXPECT_EQ(a.radiance, b.radiance);
  EXPECT_EQ(a.solidAngle, b.solidAngle);
  EXPECT_EQ(a.angularRadius, b.angularRadius);
  EXPECT_EQ(a.x0, b.x0);
  EXPECT_EQ(a.y0, b.y0);
  EXPECT_EQ(a.x1, b.x1);
  EXPECT_EQ(a.y1, b.y1);
  EXPECT_EQ(a.sh9.coefficients, b.sh9.coefficients);
}

TEST(EnvironmentLightsJson, ReadsBackWhatItWroteToTheLastBit) {
  const fs::path file = test::scratchDir() / "lights.json";
  const EnvironmentLights lights = testLights();
  writeEnvironmentLightsJson(file, lights);
  const EnvironmentLights read = readEnvironmentLightsJson(file);
  EXPECT_EQ(read.sunThreshold, lights.sunThreshold);
  EXPECT_EQ(read.medianCutLevels, lights.medianCutLevels);
  ASSERT_EQ(read.suns.size(), 2u);
  ASSERT_EQ(read.medianCut.size(), 1u);
  for (std::size_t i = 0; i < 2; ++i) expectSameLight(read.suns[i], lights.suns[i]);
  expectSameLight(read.medianCut[0], lights.medianCut[0]);
  // No lights at all is a valid file.
  writeEnvironmentLightsJson(file, EnvironmentLights{});
  const EnvironmentLights none = readEnvironmentLightsJson(file);
  EXPECT_TRUE(none.suns.empty());
  EXPECT_TRUE(none.medianCut.empty());
}

TEST(EnvironmentLightsJson, RefusesToWriteNonFiniteValuesAndLeavesNoFile) {
  const fs::path folder = test::scratchDir();
  const fs::path file = folder / "lights.json";
  EnvironmentLights lights = testLights();
  lights.medianCut[0].radiance.g = INFINITY;
  EXPECT_EQ(test::errorMessage([&] { writeEnvironmentLightsJson(file, lights); }),
            file.string() + ": cannot write non-finite medianCut[0].radiance");
  EXPECT_TRUE(fs::is_empty(folder));
}

// The file written by testLights() with `from` replaced by `to` (which must occur).
fs::path editedFile(const std::string& name, const std::string& from, const std::string& to) {
  const fs::path file = test::scratchDir() / name;
  writeEnvironmentLightsJson(file, testLights());
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(file, std::ios::trunc) << text;
  return file;
}

TEST(EnvironmentLightsJson, BadFilesAreOneLineErrorsNamingTheFileAndTheEntry) {
  const fs::path missing = test::scratchDir() / "none.json";
  EXPECT_NE(test::errorMessage([&] { readEnvironmentLightsJson(missing); }).find(missing.string() + ": "),
            std::string::npos);
  struct Case {
    const char *from, *to, *problem;
  };
  const Case cases[] = {
      {"\"sunThreshold\": 21.8270741", "\"sunThreshold\": -1", "sunThreshold: negative"},
      {"\"sunThreshold\"", "\"threshold\"", "lights: missing \"sunThreshold\""},
      {"\"medianCutLevels\": 4", "\"medianCutLevels\": 13", "medianCutLevels: expected 0..12"},
      {"\"medianCutLevels\": 4", "\"medianCutLevels\": 4.5", "medianCutLevels: expected an integer"},
      {"\"kind\": \"iblkit environment lights\"", "\"kind\": \"lights\"",
       "kind: expected \"iblkit environment lights\" (not an iblkit lights file)"},
      {"\"direction\": [", "\"direction\": [2, ", "suns[0].direction: expected 3 numbers"},
      {"\"direction\": [", "\"direction\": [1e39, 0, 0], \"x\": [",
       "suns[0].direction: expected a finite number"},
      {"\"irradiance\": [", "\"irradiance\": [1, 1e39, 1], \"x\": [",
       "suns[0].irradiance: expected a finite number"},
      {"\"irradiance\": [", "\"irradiance\": [-1, 1, 1], \"x\": [", "suns[0].irradiance: negative"},
      {"\"solidAngle\": ", "\"solidAngle\": 13, \"x\": ",
       "suns[0].solidAngle: expected a solid angle in (0, 4 pi]"},
      {"\"angularRadius\": ", "\"angularRadius\": -1, \"x\": ",
       "suns[0].angularRadius: expected an angle in [0, pi]"},
      {"\"angularRadius\": ", "\"angularRadius\": 0.2, \"x\": ",
       "suns[0].angularRadius: wider than a sun (at most 10 degrees, 0.1745 radians)"},
      {"\"texels\": [299, 55, 515, 64]", "\"texels\": [299, 55, 299, 64]", "suns[0].texels: empty rectangle"},
      {"\"texels\": [299, 55, 515, 64]", "\"texels\": [299, 55, 515]",
       "suns[0].texels: expected [x0, y0, x1, y1]"},
      {"\"sh9\": [[", "\"sh9\": [[0, 0, 0]], \"x\": [[", "suns[0].sh9: expected 9 RGB coefficients"},
      {"\"direction\": [", "\"direction\": [\"a\", 0, 0], \"x\": [", "suns[0].direction: expected a number"},
      {"\"medianCut\": [", "\"medianCut\": {\"a\": 1}, \"x\": [", "medianCut: expected a list"},
  };
  int n = 0;
  for (const Case& c : cases) {
    const fs::path file = editedFile("bad" + std::to_string(n++) + ".json", c.from, c.to);
    EXPECT_EQ(test::errorMessage([&] { readEnvironmentLightsJson(file); }), file.string() + ": " + c.problem)
        << c.to;
  }
  // A unit direction is checked after its numbers.
  const fs::path skewed =
      editedFile("skewed.json", "\"direction\": [", "\"direction\": [0.5, 0.5, 0.5], \"x\": [");
  EXPECT_EQ(test::errorMessage([&] { readEnvironmentLightsJson(skewed); }),
            skewed.string() + ": suns[0].direction: not a unit vector");
  const fs::path broken = editedFile("broken.json", "{", "{{");
  const std::string message = test::errorMessage([&] { readEnvironmentLightsJson(broken); });
  EXPECT_EQ(message.rfind(broken.string() + ": not valid JSON: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace iblkit
