#include "reference/renderer.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/relative_squared_error.h"
#include "core/scene_environment.h"
#include "reference/test_scenes.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

using test::integratorOf;

// A glossy sphere on a ground under a sky that is brighter above: every part of the path
// tracer takes part (ground, several bounces, Russian roulette).
Scene groundedScene() {
  Scene scene = test::sphereScene(test::lambert(0.7f));
  Material ground = test::lambert(0.4f);
  scene.materials[0].roughness = 0.3f;
  scene.materials[0].specular = 1.0f;
  scene.materials.push_back(ground);
  scene.meshes.push_back(test::meshFrom(plane(glm::vec3(0.0f, -1.0f, 0.0f), 20.0f), 1, true));
  return scene;
}

EnvironmentMap sky() {
  Image map(32, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) map.at(x, y) = glm::vec4(glm::vec3(y < 8 ? 2.0f + x % 3 : 0.3f), 1.0f);
  return EnvironmentMap::fromImage(std::move(map), "sky.exr");
}

TEST(Render, SameSeedGivesTheSameImageWhateverTheThreadCount) {
  const EnvironmentMap environment = sky();
  const auto image = [&](std::uint32_t seed, int threads) {
    return test::renderWith(groundedScene(), environment, integratorOf(IntegratorKind::Path), 40, 8, seed,
                            threads)
        .beauty.pixels();
  };
  const std::vector<glm::vec4> one = image(9, 1);
  EXPECT_EQ(one, image(9, 2));
  EXPECT_EQ(one, image(9, 3));
  EXPECT_NE(one, image(10, 2));
}

TEST(Render, LayersDescribeTheFirstHit) {
  const RenderResult r = test::renderWith(groundedScene(), sky(), integratorOf(IntegratorKind::Path), 32, 16);
  EXPECT_EQ(r.samplesPerPixel, 16);
  EXPECT_GT(r.rays, 32u * 32u * 16u);
  // The centre pixel sees the sphere's front: normal +Z, distance 3, albedo 0.7, mask 1.
  EXPECT_NEAR(r.normal.at(16, 16).z, 1.0f, 0.01f);
  EXPECT_NEAR(r.depth.at(16, 16).r, 3.0f, 0.01f);
  EXPECT_NEAR(r.albedo.at(16, 16).r, 0.7f, 1e-5f);
  EXPECT_EQ(r.mask.at(16, 16).r, 1.0f);
  // The bottom corner sees the ground (no object), the top corner the sky (nothing at all).
  EXPECT_EQ(r.mask.at(0, 31).r, 0.0f);
  EXPECT_NEAR(r.albedo.at(0, 31).r, 0.4f, 1e-5f);
  EXPECT_EQ(r.depth.at(0, 0).r, 0.0f);
  // Somewhere on the sphere the estimate is noisy: the variance layer shows it.
  EXPECT_GT(r.variance.stats().max.r, 0.0f);
}

// relMSE of b against a over the pixels (the scorer's term, core/relative_squared_error.h).
double relativeMse(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) sum += relativeSquaredError(a.pixels()[i][c], b.pixels()[i][c]);
  return sum / (3.0 * double(a.pixels().size()));
}

// The bunny on its ground placed 3,000 units from the origin, or shrunk 1,000 times, renders the
// image it renders where it stands (the camera frames its bounds; the same seed). The rays leave
// each hit point by the point's own rounding (raytrace/ray_offset.h): with the 256-ulp offset the
// shifted bunny's creases lost their shadows (relMSE 4.5e-3 here, more than another seed's noise,
// 3.2e-3) and the shrunk one's contacts moved (1.3e-3); now 7e-5 (the geometry's own rounding at
// 3,000 units) and 4e-8.
TEST(Render, TheImageDoesNotDependOnWhereTheSceneStandsOrOnItsSize) {
  const std::filesystem::path file = test::assetsDir() / "scenes" / "bunny.json";
  if (!std::filesystem::exists(test::assetsDir() / "models" / "bunny.glb")) GTEST_SKIP() << "assets not fetched";
  const Scene original = loadScene(file);
  const EnvironmentMap environment = loadSceneEnvironment(original);
  const auto image = [&](float scale, glm::vec3 shift) {
    Scene scene = original;
    for (Mesh& mesh : scene.meshes)
      for (glm::vec3& p : mesh.positions) p = scale * p + shift;
    scene.bounds = objectBounds(scene.meshes);
    return test::renderWith(std::move(scene), environment, integratorOf(IntegratorKind::Path), 96, 16, 3)
        .beauty;
  };
  const Image here = image(1.0f, glm::vec3(0.0f));
  const double far = relativeMse(here, image(1.0f, glm::vec3(3000.0f, 0.0f, -3000.0f)));
  const double small = relativeMse(here, image(1e-3f, glm::vec3(0.0f)));
  EXPECT_LT(far, 4e-4);
  EXPECT_LT(small, 1e-5);
}

TEST(Render, RefusesBadSettings) {
  const EnvironmentMap environment = EnvironmentMap::constant(glm::vec3(1.0f));
  const RenderScene scene(test::sphereScene(test::lambert(1.0f)));
  const EnvironmentSampler sampler(environment);
  const Integrator integrator(scene, environment, sampler, IntegratorSettings{});
  const Camera camera = sceneCamera(scene.scene(), 1.0f);
  const auto message = [&](int width, int height, int spp, int threads) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samplesPerPixel = spp;
    settings.threads = threads;
    return test::errorMessage([&] { render(integrator, camera, settings); });
  };
  EXPECT_EQ(message(0, 8, 1, 1), "render: image size 0x8 is outside 1..16384");
  EXPECT_EQ(message(8, -3, 1, 1), "render: image size 8x-3 is outside 1..16384");
  EXPECT_EQ(message(16385, 8, 1, 1), "render: image size 16385x8 is outside 1..16384");
  EXPECT_EQ(message(8, 8, 0, 1), "render: samples per pixel 0 is outside 1..16777216");
  EXPECT_EQ(message(8, 8, 1, -1), "render: thread count -1 is outside 0..1024");
  EXPECT_EQ(message(8, 8, 1, 70000), "render: thread count 70000 is outside 0..1024");
}

}  // namespace
}  // namespace iblkit
