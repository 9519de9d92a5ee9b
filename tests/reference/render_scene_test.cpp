#include "reference/render_scene.h"

#include <gtest/gtest.h>

#include "core/procedural_mesh.h"
#include "core/surface_material.h"
#include "reference/test_scenes.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A unit sphere of material 0 standing on a ground of material 1, with an empty mesh between.
RenderScene sphereOnGround() {
  Scene scene;
  scene.materials = {test::lambert(0.8f), test::lambert(0.3f)};
  scene.meshes.push_back(test::meshFrom(uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 32, 64), 0));
  scene.meshes.push_back(Mesh{});
  scene.meshes.push_back(test::meshFrom(plane(glm::vec3(0.0f), 20.0f), 1, true));
  return RenderScene(std::move(scene));
}

SurfacePoint shade(const RenderScene& scene, const Ray& ray) {
  const Hit hit = scene.rays().intersect(ray, 0.0f, kInfinity);
  EXPECT_TRUE(hit.hit);
  return scene.surfacePoint(hit, -ray.direction);
}

TEST(RenderScene, HitsMapBackToTheirMeshAndMaterial) {
  const RenderScene scene = sphereOnGround();
  const SurfacePoint sphere = shade(scene, Ray{{0.0f, 1.0f, 5.0f}, {0.0f, 0.0f, -1.0f}});
  EXPECT_EQ(sphere.material, &scene.scene().materials[0]);
  EXPECT_FALSE(sphere.isGround);
  EXPECT_NEAR(sphere.position.z, 1.0f, 2e-3f);
  EXPECT_NEAR(sphere.shadingNormal.z, 1.0f, 1e-5f);

  const SurfacePoint ground = shade(scene, Ray{{5.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}});
  EXPECT_EQ(ground.material, &scene.scene().materials[1]);
  EXPECT_TRUE(ground.isGround);
  EXPECT_FLOAT_EQ(ground.geometricNormal.y, 1.0f);
  EXPECT_FLOAT_EQ(ground.shadingNormal.y, 1.0f);
}

// Seen from below (inside the sphere, under the ground), both normals turn towards the viewer.
TEST(RenderScene, NormalsFaceTheViewer) {
  const RenderScene scene = sphereOnGround();
  const SurfacePoint inside = shade(scene, Ray{{0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  EXPECT_LT(inside.geometricNormal.x, -0.99f);
  EXPECT_LT(inside.shadingNormal.x, -0.99f);
  const SurfacePoint below = shade(scene, Ray{{5.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
  EXPECT_FLOAT_EQ(below.geometricNormal.y, -1.0f);
  EXPECT_FLOAT_EQ(below.shadingNormal.y, -1.0f);
}

// Interpolated normals that face away from the viewer (a grazing view where the vertex normals
// lean away, as at silhouettes of coarse meshes) are turned towards it until they face it by
// kMinShadingCosine (shadingNormalFacingViewer), in the plane of the normal and the viewer.
TEST(RenderScene, ShadingNormalNeverFacesAwayFromTheViewer) {
  Scene scene;
  scene.materials = {test::lambert(1.0f)};
  Mesh triangle;
  triangle.positions = {{-1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}};
  triangle.normals.assign(3, glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f)));
  triangle.indices = {0, 1, 2};
  scene.meshes = {triangle};
  const RenderScene leaning(std::move(scene));
  // wo = (-1, 0.1, 0) normalised: above the triangle (y > 0) but behind the leaning normal.
  const Ray ray{{-1.0f, 0.1f, 0.0f}, glm::normalize(glm::vec3(1.0f, -0.1f, 0.0f))};
  const SurfacePoint grazing = shade(leaning, ray);
  EXPECT_EQ(grazing.geometricNormal, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_NEAR(glm::dot(grazing.shadingNormal, -ray.direction), kMinShadingCosine, 1e-6f);
  EXPECT_NEAR(glm::length(grazing.shadingNormal), 1.0f, 1e-6f);
  EXPECT_NEAR(grazing.shadingNormal.z, 0.0f, 1e-6f) << "in the plane of the normal and the viewer";
  EXPECT_GT(grazing.shadingNormal.y, 0.0f);
  // Seen from the other side the leaning normal faces the viewer and is kept.
  const SurfacePoint facing =
      shade(leaning, Ray{{1.0f, 0.1f, 0.0f}, glm::normalize(glm::vec3(-1.0f, -0.1f, 0.0f))});
  EXPECT_NEAR(facing.shadingNormal.x, triangle.normals[0].x, 1e-6f);
}

TEST(RenderScene, RefusesMaterialIndicesOutOfRange) {
  Scene scene;
  scene.file = "broken.json";
  scene.materials = {test::lambert(1.0f)};
  scene.meshes = {test::meshFrom(uvSphere(glm::vec3(0.0f), 1.0f, 4, 6), 2)};
  scene.meshes[0].name = "ball";
  EXPECT_EQ(test::errorMessage([&] { RenderScene{std::move(scene)}; }),
            "broken.json: mesh 'ball' uses material 2, but the scene has 1");
}

}  // namespace
}  // namespace iblkit
