// Interreflected SH transfer (VisibilitySettings::bounces, Sloan et al. 2002): light bounced
// between surfaces adds transfer where surfaces see each other, and nothing where none does.
#include <gtest/gtest.h>

#include <cstring>

#include "baker/vertex_visibility.h"
#include "core/procedural_mesh.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

// A concave configuration: a floor grid meeting a tall wall (the box's +X face is x = 0) at a
// right angle; floor vertices near the wall see the wall, which sees them back.
std::vector<Mesh> floorAndWall() {
  Mesh floor;
  floor.name = "floor";
  constexpr int kCells = 8;
  for (int i = 0; i <= kCells; ++i)
    for (int j = 0; j <= kCells; ++j) {
      floor.positions.emplace_back(0.01f + 0.5f * float(j), 0.0f, -2.0f + 0.5f * float(i));
      floor.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  for (std::uint32_t i = 0; i < kCells; ++i)
    for (std::uint32_t j = 0; j < kCells; ++j) {
      const std::uint32_t a = i * (kCells + 1) + j, b = a + kCells + 1, c = b + 1, d = a + 1;
      floor.indices.insert(floor.indices.end(), {a, b, c, a, c, d});
    }
  return {floor, toMesh(box(glm::vec3(-0.5f, 2.0f, 0.0f), glm::vec3(1.0f, 4.0f, 6.0f)), "wall")};
}

VisibilitySettings withBounces(int bounces, std::vector<float> albedo) {
  VisibilitySettings settings;
  settings.rayCount = 256;
  settings.bounces = bounces;
  settings.albedo = std::move(albedo);
  return settings;
}

TEST(InterreflectedTransfer, ConcaveCornerGainsTransferThatConverges) {
  const std::vector<Mesh> meshes = floorAndWall();
  VisibilityStatistics statistics;
  const auto shadowed = bakeVertexVisibility(meshes, withBounces(0, {}));
  const auto one = bakeVertexVisibility(meshes, withBounces(1, {0.8f, 0.8f}), &statistics);
  const auto two = bakeVertexVisibility(meshes, withBounces(2, {0.8f, 0.8f}));
  EXPECT_EQ(statistics.bounceRays, statistics.rays);  // one bounce re-traces every ray once
  const std::size_t nearWall = 4 * 9;                 // the floor vertex at (0.01, 0, 0)
  ASSERT_LT(glm::distance(meshes[0].positions[nearWall], glm::vec3(0.01f, 0.0f, 0.0f)), 1e-6f);
  const float t0 = shadowed[0].transfer[nearWall][0], t1 = one[0].transfer[nearWall][0],
              t2 = two[0].transfer[nearWall][0];
  // The wall fills half the hemisphere and is lit by most of the sky: the first bounce adds a
  // sizeable fraction (albedo 0.8 times the wall's mean transfer seen from here), the second far
  // less.
  EXPECT_GT(t1, t0 * 1.15f);
  EXPECT_GT(t2, t1);
  EXPECT_LT(t2 - t1, 0.5f * (t1 - t0));
  // Nothing else changes.
  EXPECT_EQ(one[0].ambientOcclusion, shadowed[0].ambientOcclusion);
  EXPECT_EQ(one[0].bentNormals, shadowed[0].bentNormals);
  // Every floor vertex that sees the wall gains constant (t0) transfer.
  for (std::size_t v = 0; v < meshes[0].vertexCount(); ++v)
    EXPECT_GE(one[0].transfer[v][0], shadowed[0].transfer[v][0]) << "vertex " << v;
}

TEST(InterreflectedTransfer, BlackSurfacesReflectNothing) {
  const std::vector<Mesh> meshes = floorAndWall();
  const auto shadowed = bakeVertexVisibility(meshes, withBounces(0, {}));
  const auto black = bakeVertexVisibility(meshes, withBounces(3, {0.0f, 0.0f}));
  for (std::size_t m = 0; m < meshes.size(); ++m)
    EXPECT_EQ(std::memcmp(black[m].transfer.data(), shadowed[m].transfer.data(),
                          meshes[m].vertexCount() * sizeof(ShBasis9)),
              0);
}

// The transfer is of irradiance (the vertex's own albedo multiplies it in the shader): what a
// bounce adds at a vertex is the light its surroundings reflect, so it scales with the albedo of
// the mesh its rays hit and not with its own. The floor near the wall gains in proportion to the
// wall's albedo and the same whatever the floor's; the wall's gain near the floor, to the floor's.
TEST(InterreflectedTransfer, TheReflectorsAlbedoScalesTheBounce) {
  const std::vector<Mesh> meshes = floorAndWall();
  const auto shadowed = bakeVertexVisibility(meshes, withBounces(0, {}));
  const auto darkWall = bakeVertexVisibility(meshes, withBounces(1, {0.8f, 0.2f}));
  const auto brightWall = bakeVertexVisibility(meshes, withBounces(1, {0.8f, 0.8f}));
  const auto darkFloor = bakeVertexVisibility(meshes, withBounces(1, {0.2f, 0.8f}));
  const std::size_t nearWall = 4 * 9;  // the floor vertex at (0.01, 0, 0)
  const float t0 = shadowed[0].transfer[nearWall][0];
  const float dark = darkWall[0].transfer[nearWall][0] - t0, bright = brightWall[0].transfer[nearWall][0] - t0;
  ASSERT_GT(dark, 0.0f);
  EXPECT_NEAR(bright / dark, 4.0f, 1e-3f);
  // The floor's own albedo does not change what it receives.
  EXPECT_FLOAT_EQ(darkFloor[0].transfer[nearWall][0], brightWall[0].transfer[nearWall][0]);
  // The wall's lowest vertices receive from the floor: 0.2 against 0.8 of it.
  double fromDarkFloor = 0.0, fromBrightFloor = 0.0;
  for (std::size_t v = 0; v < meshes[1].vertexCount(); ++v) {
    fromDarkFloor += darkFloor[1].transfer[v][0] - shadowed[1].transfer[v][0];
    fromBrightFloor += brightWall[1].transfer[v][0] - shadowed[1].transfer[v][0];
  }
  ASSERT_GT(fromDarkFloor, 0.0);
  EXPECT_NEAR(fromBrightFloor / fromDarkFloor, 4.0, 1e-3);
}

TEST(InterreflectedTransfer, LoneConvexSphereIsUnchanged) {
  const std::vector<Mesh> meshes = {toMesh(uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 12, 24), "sphere")};
  VisibilityStatistics statistics;
  const auto shadowed = bakeVertexVisibility(meshes, withBounces(0, {}));
  const auto bounced = bakeVertexVisibility(meshes, withBounces(2, {1.0f}), &statistics);
  EXPECT_EQ(statistics.bounceRays, 2 * statistics.rays);
  EXPECT_EQ(std::memcmp(bounced[0].transfer.data(), shadowed[0].transfer.data(),
                        meshes[0].vertexCount() * sizeof(ShBasis9)),
            0);
}

TEST(InterreflectedTransfer, NeedsOneAlbedoPerMeshInRange) {
  const std::vector<Mesh> meshes = floorAndWall();
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, withBounces(1, {0.5f})); }),
            "vertex visibility: bounces need one albedo per mesh: got 1 for 2 meshes");
  EXPECT_EQ(test::errorMessage([&] {
              bakeVertexVisibility(meshes, withBounces(1, {0.5f, 1.5f}));
            }),
            "vertex visibility: albedo 1.500000 is not in [0, 1]");
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, withBounces(-1, {})); }),
            "vertex visibility: bounces must be >= 0");
}

}  // namespace
}  // namespace iblkit
