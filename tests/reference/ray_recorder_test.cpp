#include "reference/ray_recorder.h"

#include <gtest/gtest.h>

#include "reference/test_scenes.h"

namespace iblkit {
namespace {

// A Lambert sphere on a ground plane under a constant sky: closest-hit and shadow rays both occur.
struct Fixture {
  Scene scene = [] {
    Scene s = test::sphereScene(test::lambert(0.6f));
    s.materials.push_back(test::lambert(0.4f));
    s.meshes.push_back(test::meshFrom(plane(glm::vec3(0.0f, -1.0f, 0.0f), 20.0f), 1, true));
    return s;
  }();
  Camera camera = sceneCamera(scene, 1.0f);
  RenderScene renderScene{scene};
  EnvironmentMap environment = EnvironmentMap::constant(glm::vec3(1.0f));
  EnvironmentSampler sampler{environment};
  Integrator integrator{renderScene, environment, sampler, test::integratorOf(IntegratorKind::Path)};

  RenderResult render(int threads) const {
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.samplesPerPixel = 4;
    settings.threads = threads;
    return iblkit::render(integrator, camera, settings);
  }
};

// Every ray the renderer counts is recorded, as closest-hit or shadow query, and recording does
// not change the image.
TEST(RayRecorder, RecordsEveryRayTracedWithoutChangingTheImage) {
  Fixture f;
  const RenderResult plain = f.render(2);
  RayRecorder recorder;
  f.integrator.recordRays(&recorder);
  const RenderResult recorded = f.render(2);
  EXPECT_EQ(recorded.beauty.pixels(), plain.beauty.pixels());
  EXPECT_EQ(recorder.size(), recorded.rays);
  const std::vector<RecordedRay> rays = recorder.rays();
  ASSERT_EQ(rays.size(), recorded.rays);
  std::size_t shadow = 0, camera = 0;
  for (const RecordedRay& ray : rays) {
    shadow += ray.occlusion;
    // The query as the alpha filter saw it: one camera ray per sample, every other one secondary.
    camera += ray.query.kind == RayKind::Camera;
    EXPECT_TRUE(!ray.occlusion || ray.query.kind == RayKind::Secondary);
    EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-4f);
    EXPECT_EQ(ray.tmin, 0.0f);
  }
  EXPECT_GT(shadow, 0u);
  EXPECT_EQ(camera, std::size_t{16 * 16 * 4});
  EXPECT_GE(rays.size() - shadow, camera);

  // Replayed through the scene, the closest-hit queries hit as often as the render's did: the
  // camera rays that hit the sphere or ground (mask or depth non-zero) are among them.
  std::size_t hits = 0;
  for (const RecordedRay& ray : rays)
    if (!ray.occlusion)
      hits += f.renderScene.rays().intersect({ray.origin, ray.direction}, ray.tmin, ray.tmax).hit;
  EXPECT_GT(hits, 0u);

  // Off again: nothing more is recorded; clear() empties it.
  f.integrator.recordRays(nullptr);
  f.render(1);
  EXPECT_EQ(recorder.size(), recorded.rays);
  recorder.clear();
  EXPECT_EQ(recorder.size(), 0u);
}

}  // namespace
}  // namespace iblkit
