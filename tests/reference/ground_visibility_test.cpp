#include "reference/ground_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/procedural_mesh.h"
#include "reference/render_scene.h"
#include "reference/test_scenes.h"

namespace iblkit {
namespace {

// A ground at y = -1.5 and, unless `objects` is false, a square slab of half-side 3 whose underside
// is at y = 0.
Scene slabOverGround(bool objects = true) {
  Scene scene;
  scene.materials = {test::lambert(0.5f)};
  if (objects) scene.meshes.push_back(test::meshFrom(box(glm::vec3(0.0f, 0.05f, 0.0f), glm::vec3(6.0f, 0.1f, 6.0f)), 0));
  scene.meshes.push_back(test::meshFrom(plane(glm::vec3(0.0f, -1.5f, 0.0f), 200.0f), 0, true));
  scene.bounds = objectBounds(scene.meshes);
  return scene;
}

GroundVisibility visibilityOf(const Scene& scene, const RenderScene& render, const EnvironmentMap& map,
                              const EnvironmentSampler& sampler) {
  const auto ground = GroundOcclusion::of(scene, map);
  EXPECT_TRUE(ground.has_value());
  return GroundVisibility(*ground, render.rays(), sampler);
}

// Under a constant sky the visible fraction is 1 minus the slab's form factor: below its centre, at
// height h under a square of half-side s, four corner rectangles of F(X, Y) = (X / sqrt(1 + X^2)
// atan(Y / sqrt(1 + X^2)) + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))) / (2 pi), X = Y = s / h:
// 0.169 here; 32 probes give it within 0.06. Outside the grid it is 1, and between the nodes the
// bilinear mean of the nodes around.
TEST(GroundVisibility, IsTheVisibleFractionOfTheSky) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f));
  const Scene scene = slabOverGround();
  const RenderScene render{Scene(scene)};
  const EnvironmentSampler sampler(map);
  const GroundVisibility visibility = visibilityOf(scene, render, map, sampler);
  ASSERT_FALSE(visibility.empty());
  const double x = 3.0 / 1.5, root = std::sqrt(1.0 + x * x);
  const double formFactor = 4.0 * (2.0 * x / root * std::atan(x / root)) / (2.0 * std::numbers::pi);
  const int centre = GroundVisibility::kNodes / 2;
  EXPECT_NEAR(visibility.node(centre, centre), 1.0 - formFactor, 0.06);
  EXPECT_NEAR(visibility.at(glm::vec3(0.0f, -1.5f, 0.0f)), 1.0 - formFactor, 0.06);
  // Farther out more of the sky shows, and beyond the square (half-side 4 x the slab's bounding
  // radius, about 17) it is 1.
  EXPECT_GT(visibility.node(centre + 8, centre), visibility.node(centre, centre) + 0.3f);
  EXPECT_EQ(visibility.at(glm::vec3(40.0f, -1.5f, 0.0f)), 1.0f);
  const float a = visibility.node(centre + 3, centre), b = visibility.node(centre + 4, centre);
  EXPECT_NE(a, b);
  const float spacing = 2.0f * GroundVisibility::kExtent * 4.2427f / float(GroundVisibility::kNodes - 1);
  EXPECT_NEAR(visibility.at(glm::vec3(3.5f * spacing, -1.5f, 0.0f)), 0.5f * (a + b), 0.01f);
}

// Nothing above the ground: 1 everywhere (no grid).
TEST(GroundVisibility, IsOneWithoutObjects) {
  const EnvironmentMap map = test::spotEnvironment();
  const Scene scene = slabOverGround(false);
  const RenderScene render{Scene(scene)};
  const EnvironmentSampler sampler(map);
  const GroundVisibility visibility = visibilityOf(scene, render, map, sampler);
  EXPECT_TRUE(visibility.empty());
  EXPECT_EQ(visibility.at(glm::vec3(0.0f, -1.5f, 0.0f)), 1.0f);
}

}  // namespace
}  // namespace iblkit
