// The visibility bake's options: the distance falloff of the occlusion (--ao-falloff) and area
// sampling over the vertex's one-ring (--ao-area), against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "baker/vertex_visibility.h"
#include "core/procedural_mesh.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

// A floor of 3 x 3 vertices (square cells of side 5, a vertex at the origin) under a ceiling whose
// underside is the plane y = h, wide enough to be infinite within distance 1.
std::vector<Mesh> floorUnderCeiling(float h) {
  Mesh floor;
  floor.name = "floor";
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      floor.positions.emplace_back(-5.0f + 5.0f * float(j), 0.0f, -5.0f + 5.0f * float(i));
      floor.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  for (std::uint32_t i = 0; i < 2; ++i)
    for (std::uint32_t j = 0; j < 2; ++j) {
      const std::uint32_t a = 3 * i + j, b = a + 3, c = a + 4, d = a + 1;
      floor.indices.insert(floor.indices.end(), {a, b, c, a, c, d});
    }
  return {floor, toMesh(box(glm::vec3(0.0f, h + 0.5f, 0.0f), glm::vec3(400.0f, 1.0f, 400.0f)), "ceiling")};
}

constexpr std::size_t kCentre = 4;  // the floor vertex at the origin

VisibilitySettings settings(float maxDistance, float falloff, bool area = false) {
  VisibilitySettings s;
  s.rayCount = 4096;
  s.maxDistance = maxDistance;
  s.falloff = falloff;
  s.areaSampling = area;
  return s;
}

// With the ceiling at height h and c = cos(theta), a ray hits it at t = h / c; within D when
// c > c0 = h / D. Its occlusion is (1 - c0 / c)^p, and AO = 1 - integral over c in (c0, 1) of
// (1 - c0 / c)^p 2c dc:
//   p = 0 (hard cutoff): AO = c0^2;   p = 1: AO = 1 - (1 - c0)^2;
//   p = 2: AO = 1 - [(1 - c0^2) - 4 c0 (1 - c0) + 2 c0^2 ln(1 / c0)].
TEST(VisibilityFalloff, FloorUnderACeilingMatchesTheClosedForm) {
  const std::vector<Mesh> meshes = floorUnderCeiling(0.5f);
  const float c0 = 0.5f;
  EXPECT_NEAR(bakeVertexVisibility(meshes, settings(1.0f, 0.0f))[0].ambientOcclusion[kCentre], c0 * c0,
              0.01f);
  EXPECT_NEAR(bakeVertexVisibility(meshes, settings(1.0f, 1.0f))[0].ambientOcclusion[kCentre],
              1.0f - (1.0f - c0) * (1.0f - c0), 0.01f);
  const float p2 = (1.0f - c0 * c0) - 4.0f * c0 * (1.0f - c0) + 2.0f * c0 * c0 * std::log(1.0f / c0);
  EXPECT_NEAR(bakeVertexVisibility(meshes, settings(1.0f, 2.0f))[0].ambientOcclusion[kCentre], 1.0f - p2,
              0.01f);
}

TEST(VisibilityFalloff, NeedsAMaximumDistanceAndAValidExponent) {
  const std::vector<Mesh> meshes = floorUnderCeiling(0.5f);
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, settings(0.0f, 1.0f)); }),
            "vertex visibility: a falloff needs a maximum distance (--ao-distance > 0)");
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, settings(1.0f, -1.0f)); }),
            "vertex visibility: falloff exponent must be finite and >= 0");
}

// Under an infinite ceiling every point of the floor sees the same: area sampling must give the
// vertex's value (its origins, normals and rejection are right).
TEST(VisibilityAreaSampling, UniformSurroundingsGiveThePointValue) {
  const std::vector<Mesh> meshes = floorUnderCeiling(0.5f);
  const auto result = bakeVertexVisibility(meshes, settings(1.0f, 1.0f, true));
  EXPECT_NEAR(result[0].ambientOcclusion[kCentre], 0.75f, 0.02f);
  EXPECT_NEAR(result[0].ambientOcclusion[0], 0.75f, 0.02f);  // a corner: a one-ring of one triangle
}

TEST(VisibilityAreaSampling, LoneConvexSphereStaysOpen) {
  const std::vector<Mesh> meshes = {toMesh(uvSphere(glm::vec3(0.0f), 1.0f, 8, 16), "sphere")};
  VisibilitySettings s = settings(0.0f, 0.0f, true);
  s.rayCount = 256;
  const auto result = bakeVertexVisibility(meshes, s);
  for (std::size_t v = 0; v < meshes[0].vertexCount(); ++v)
    EXPECT_EQ(result[0].ambientOcclusion[v], 1.0f) << v;
}

// A big two-triangle floor whose corner at (-5, 0, -5) lies under a low slab covering x < -3.5:
// at the corner nearly everything is blocked, but much of the corner's share of the floor (its
// dual cell reaches the edge midpoints at x = 0) is not under the slab, which area sampling sees.
TEST(VisibilityAreaSampling, LargeTrianglesAverageOverTheVertexsShare) {
  const std::vector<Mesh> meshes = {
      toMesh(plane(glm::vec3(0.0f), 10.0f), "floor"),
      toMesh(box(glm::vec3(-4.75f, 0.7f, 0.0f), glm::vec3(2.5f, 1.0f, 12.0f)), "slab")};
  std::size_t corner = 0;
  for (std::size_t v = 0; v < meshes[0].vertexCount(); ++v)
    if (meshes[0].positions[v].x < 0.0f && meshes[0].positions[v].z < 0.0f) corner = v;
  const float point = bakeVertexVisibility(meshes, settings(0.0f, 0.0f))[0].ambientOcclusion[corner];
  const float area = bakeVertexVisibility(meshes, settings(0.0f, 0.0f, true))[0].ambientOcclusion[corner];
  EXPECT_LT(point, 0.15f);
  EXPECT_GT(area, point + 0.2f);
  std::printf("corner AO: at the vertex %.3f, over its share %.3f\n", point, area);
}

// A unit box resting on a wide floor, one quad per face (a low-poly asset's box). Every point of a
// side face sees the floor below its horizon and the sky above it, and the box is convex: its AO
// is exactly 1/2 (the cosine-weighted hemisphere of a horizontal normal, halved by the horizontal
// plane). The face's bottom vertices lie on the floor's plane: an upward ray from the vertex
// itself meets the floor at t ~ 0, and until 2026-12-07 their AO came out 0.000 (the engine's
// interpolation darkened the lower half of every such face: the `tiles` boxes in the report,
// docs/report.md "Area sampling in the report's bakes"). Sampled at the vertex, rays now start a
// thousandth of the way into its one-ring (vertexRayOrigin); over its share, off the floor anyway.
TEST(VisibilityPointSampling, AContactVertexSeesWhatItsFaceSees) {
  const std::vector<Mesh> meshes = {toMesh(plane(glm::vec3(0.0f), 400.0f), "floor"),
                                    toMesh(box(glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(1.0f)), "box")};
  const Mesh& box = meshes[1];
  for (const bool area : {false, true}) {
    const auto result = bakeVertexVisibility(meshes, settings(0.0f, 0.0f, area));
    int bottom = 0, top = 0;
    float lowest = 1.0f;
    for (std::size_t v = 0; v < box.vertexCount(); ++v) {
      if (std::abs(box.normals[v].y) > 0.5f) continue;  // the side faces only
      EXPECT_NEAR(result[1].ambientOcclusion[v], 0.5f, 0.03f)
          << (area ? "area" : "point") << " sampling, vertex " << v << " at height " << box.positions[v].y;
      ++(box.positions[v].y < 0.5f ? bottom : top);
      if (box.positions[v].y < 0.5f) lowest = std::min(lowest, result[1].ambientOcclusion[v]);
    }
    EXPECT_EQ(bottom, 8);
    EXPECT_EQ(top, 8);
    std::printf("%s sampling: lowest AO of the side faces' bottom vertices %.3f\n", area ? "area" : "point", lowest);
  }
}

TEST(VisibilityAreaSampling, SameSeedIsBitIdentical) {
  const std::vector<Mesh> meshes = floorUnderCeiling(0.5f);
  VisibilitySettings s = settings(1.0f, 0.0f, true);
  s.rayCount = 64;
  const auto first = bakeVertexVisibility(meshes, s), second = bakeVertexVisibility(meshes, s);
  for (std::size_t m = 0; m < meshes.size(); ++m)
    EXPECT_EQ(first[m].ambientOcclusion, second[m].ambientOcclusion);
}

}  // namespace
}  // namespace iblkit
