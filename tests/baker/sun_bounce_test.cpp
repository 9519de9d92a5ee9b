// The suns' bounced light per vertex (bakeSunBounce, docs/dominant-lights.md "Bounce light of the
// suns"): a floor vertex at the foot of a tall, wide wall sees the wall over half of its
// cosine-weighted hemisphere, so it gathers half of what the wall reflects.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "core/procedural_mesh.h"
#include "support/error_capture.h"
#include "support/floor_at_wall.h"

namespace iblkit {
namespace {

// A floor fan around vertex 0 at (1e-3, 0, 0) and a wall box whose +X face is the plane x = 0:
// every direction from vertex 0 with x < 0 hits the wall (support/floor_at_wall.h).
using test::floorAtWall;

// A finely cut wall, the plane x = 0 facing +X, y in [0, 4], z in [-4, 4], in 0.25 squares (so
// that the light it gathers near the floor shows at its vertices), on a floor fan around vertex 0
// at (d, 0, 0) that runs on under the wall to x = -1 (the wall's lowest vertices see it from its
// own plane).
std::vector<Mesh> floorAtWallGrid() {
  std::vector<Mesh> meshes = floorAtWall();
  Mesh& floor = meshes[0];
  floor.positions.push_back({-1, 0, -5});
  floor.positions.push_back({-1, 0, 5});
  floor.normals.assign(floor.positions.size(), glm::vec3(0, 1, 0));
  floor.indices.insert(floor.indices.end(), {0, 4, 5, 0, 5, 6, 0, 6, 1});
  Mesh& wall = meshes[1];
  wall = Mesh{};
  wall.name = "wall grid";
  constexpr int kRows = 16, kColumns = 32;
  for (int i = 0; i <= kRows; ++i)
    for (int j = 0; j <= kColumns; ++j) {
      wall.positions.emplace_back(0.0f, 0.25f * float(i), -4.0f + 0.25f * float(j));
      wall.normals.emplace_back(1.0f, 0.0f, 0.0f);
    }
  for (std::uint32_t i = 0; i < kRows; ++i)
    for (std::uint32_t j = 0; j < kColumns; ++j) {
      const std::uint32_t a = i * (kColumns + 1) + j, b = a + 1, c = a + kColumns + 1, d = c + 1;
      // Counter-clockwise seen from +X: the front face looks at the floor.
      wall.indices.insert(wall.indices.end(), {a, c, b, b, c, d});
    }
  return meshes;
}

VisibilitySettings withAlbedo(float floorAlbedo, float wallAlbedo) {
  VisibilitySettings settings;
  settings.rayCount = 4096;
  settings.albedo = {floorAlbedo, wallAlbedo};
  return settings;
}

TEST(SunBounce, FloorAtASunlitWallGathersHalfOfWhatTheWallReflects) {
  // Sun 45 degrees up on the floor's side: the wall's face takes it at cos 45 degrees, unshadowed.
  // A black floor sends nothing back, so the one bounce is all: b = (1/2) rho_wall cos 45.
  const std::vector<glm::vec3> sun = {glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f))};
  const auto bounce = bakeSunBounce(floorAtWall(), sun, withAlbedo(0.0f, 0.5f));
  ASSERT_EQ(bounce.size(), 2u);
  const float expected = 0.5f * 0.5f * std::sqrt(0.5f);
  EXPECT_NEAR(bounce[0][0].x, expected, 0.01f * expected);
  // Only the suns given have a component.
  EXPECT_EQ(bounce[0][0].y, 0.0f);
  EXPECT_EQ(bounce[0][0].w, 0.0f);
  // The wall's albedo scales it; a black wall reflects nothing.
  EXPECT_NEAR(bakeSunBounce(floorAtWall(), sun, withAlbedo(0.0f, 1.0f))[0][0].x, 2.0f * expected, 0.02f * expected);
  EXPECT_EQ(bakeSunBounce(floorAtWall(), sun, withAlbedo(0.0f, 0.0f))[0][0].x, 0.0f);
}

TEST(SunBounce, AWallLitFromBehindOrShadowedBouncesNothing) {
  // The sun beyond the wall lights its other faces, which the floor vertex does not see.
  const std::vector<glm::vec3> behind = {glm::normalize(glm::vec3(-1.0f, 1.0f, 0.0f))};
  EXPECT_EQ(bakeSunBounce(floorAtWall(), behind, withAlbedo(0.0f, 0.5f))[0][0].x, 0.0f);
  // A roof over the wall's face and the floor (a box above them, open towards -X only where the
  // wall stands) shadows the face from a sun straight above: no sunlit occluder, no bounce.
  std::vector<Mesh> meshes = floorAtWall();
  meshes.push_back(toMesh(box(glm::vec3(5.0f, 21.0f, 0.0f), glm::vec3(12.0f, 1.0f, 50.0f)), "roof"));
  VisibilitySettings settings = withAlbedo(0.0f, 0.5f);
  settings.albedo.push_back(0.5f);
  const std::vector<glm::vec3> above = {glm::normalize(glm::vec3(0.2f, 1.0f, 0.0f))};
  EXPECT_EQ(bakeSunBounce(meshes, above, settings)[0][0].x, 0.0f);
  // Without the roof the same sun lights the wall's face at cos = 0.196: it bounces.
  EXPECT_GT(bakeSunBounce(floorAtWall(), above, withAlbedo(0.0f, 0.5f))[0][0].x, 0.02f);
}

TEST(SunBounce, LightBouncesBackAndForthBetweenFloorAndWall) {
  // A sun straight above lights the floor only (the wall's face is parallel to it). The floor's
  // light reaches the wall in the first pass, and comes back to the floor vertex in the second:
  // with a black floor or wall nothing does.
  const std::vector<glm::vec3> zenith = {glm::vec3(0.0f, 1.0f, 0.0f)};
  const std::vector<Mesh> meshes = floorAtWallGrid();
  const auto both = bakeSunBounce(meshes, zenith, withAlbedo(0.8f, 0.8f));
  // The wall's foot beside the floor vertex, (0, 0, 0), sees the lit floor over half its
  // hemisphere: 0.8 / 2 from the sunlight, and a little more from what the wall's own bounce adds
  // to the floor next to it (the third pass).
  EXPECT_GT(both[1][16].x, 0.4f);
  EXPECT_LT(both[1][16].x, 0.5f);
  // The floor vertex sees the wall over half its hemisphere, lit by that bounce: rho / 2 times the
  // wall's mean bounce over what the vertex sees of it (which falls with height).
  EXPECT_GT(both[0][0].x, 0.05f);
  EXPECT_LT(both[0][0].x, 0.5f * 0.8f * 0.5f);
  EXPECT_EQ(bakeSunBounce(meshes, zenith, withAlbedo(0.0f, 0.8f))[0][0].x, 0.0f);
  EXPECT_EQ(bakeSunBounce(meshes, zenith, withAlbedo(0.8f, 0.0f))[0][0].x, 0.0f);
}

TEST(SunBounce, SameSettingsGiveTheSameBounceAndNoSunGivesNone) {
  const std::vector<glm::vec3> sun = {glm::normalize(glm::vec3(1.0f, 1.0f, 0.3f)),
                                      glm::normalize(glm::vec3(0.5f, 0.2f, -1.0f))};
  const auto a = bakeSunBounce(floorAtWall(), sun, withAlbedo(0.3f, 0.6f));
  const auto b = bakeSunBounce(floorAtWall(), sun, withAlbedo(0.3f, 0.6f));
  EXPECT_EQ(a, b);
  for (const auto& mesh : bakeSunBounce(floorAtWall(), {}, withAlbedo(0.3f, 0.6f)))
    for (const glm::vec4& v : mesh) EXPECT_EQ(v, glm::vec4(0.0f));
}

TEST(SunBounce, BadSunsAndAlbedosAreErrors) {
  const std::vector<glm::vec3> five(5, glm::vec3(0.0f, 1.0f, 0.0f));
  const std::vector<Mesh> meshes = floorAtWall();
  EXPECT_EQ(test::errorMessage([&] { bakeSunBounce(meshes, five, withAlbedo(0.5f, 0.5f)); }),
            "vertex visibility: 5 suns for the bounce, at most 4");
  const std::vector<glm::vec3> longDirection = {glm::vec3(0.0f, 2.0f, 0.0f)};
  EXPECT_EQ(test::errorMessage([&] { bakeSunBounce(meshes, longDirection, withAlbedo(0.5f, 0.5f)); }),
            "vertex visibility: a sun direction for the bounce is not unit length");
  VisibilitySettings noAlbedo = withAlbedo(0.5f, 0.5f);
  noAlbedo.albedo.pop_back();
  EXPECT_EQ(test::errorMessage([&] { bakeSunBounce(meshes, std::vector<glm::vec3>{five.front()}, noAlbedo); }),
            "vertex visibility: the sun bounce needs one albedo per mesh: got 1 for 2 meshes");
  VisibilitySettings bright = withAlbedo(0.5f, 1.5f);
  EXPECT_EQ(test::errorMessage([&] { bakeSunBounce(meshes, std::vector<glm::vec3>{five.front()}, bright); }),
            "vertex visibility: albedo 1.500000 is not in [0, 1]");
}

TEST(SunBounce, TheAttributeHoldsTheFirstFourSunsInOrder) {
  EnvironmentLights lights;
  for (int i = 0; i < 6; ++i) {
    EnvironmentLight sun;
    sun.direction = glm::normalize(glm::vec3(float(i), 1.0f, 0.0f));
    lights.suns.push_back(sun);
  }
  const std::vector<glm::vec3> directions = sunBounceDirections(lights);
  ASSERT_EQ(directions.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(directions[i], lights.suns[i].direction);
  std::vector<Mesh> meshes = floorAtWall();
  const auto bounce = bakeSunBounce(meshes, directions, withAlbedo(0.2f, 0.7f));
  attachSunBounceAttribute(meshes, bounce);
  const VertexAttribute& attribute = meshes[0].attributes.at(kSunBounceAttribute);
  EXPECT_EQ(attribute.componentCount, 4);
  ASSERT_EQ(attribute.data.size(), 4 * meshes[0].vertexCount());
  for (int c = 0; c < 4; ++c) EXPECT_EQ(attribute.data[4 * 2 + std::size_t(c)], bounce[0][2][c]);
  EXPECT_EQ(test::errorMessage([&] { attachSunBounceAttribute(meshes, {bounce[0]}); }),
            "vertex visibility attributes: 1 sun bounce results for 2 meshes");
}

}  // namespace
}  // namespace iblkit
