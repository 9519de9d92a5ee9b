#include "baker/vertex_visibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/procedural_mesh.h"
#include "support/error_capture.h"
#include "support/floor_at_wall.h"

namespace iblkit {
namespace {

// A square of side 2 * halfSize in the plane y = 0 facing +Y, cut into cells x cells squares.
Mesh groundGrid(float halfSize, int cells) {
  return toMesh(gridPlane(glm::vec3(0.0f), 2.0f * halfSize, cells), "ground");
}

std::size_t closestVertex(const Mesh& mesh, const glm::vec3& point) {
  std::size_t best = 0;
  for (std::size_t v = 1; v < mesh.vertexCount(); ++v)
    if (glm::distance(mesh.positions[v], point) < glm::distance(mesh.positions[best], point)) best = v;
  return best;
}

// A floor vertex 1e-3 from a tall, wide wall (support/floor_at_wall.h).
using test::floorAtWall;

VisibilitySettings withRays(int rays, std::uint32_t seed = 0) {
  VisibilitySettings settings;
  settings.rayCount = rays;
  settings.seed = seed;
  return settings;
}

TEST(VertexVisibility, LoneConvexSphereIsOpenWithBentNormalsAlongTheNormals) {
  const std::vector<Mesh> meshes = {toMesh(uvSphere(glm::vec3(0.3f, 1.0f, -2.0f), 1.5f, 24, 48), "sphere")};
  VisibilityStatistics statistics;
  const auto result = bakeVertexVisibility(meshes, withRays(1024), &statistics);
  ASSERT_EQ(result.size(), 1u);
  EXPECT_EQ(statistics.vertices, meshes[0].vertexCount());
  // Directions clipped by the tessellated one-ring near the horizon are re-drawn, never lost.
  EXPECT_EQ(statistics.rays, 1024 * meshes[0].vertexCount());
  EXPECT_GT(statistics.rejected, 0u);
  for (std::size_t v = 0; v < meshes[0].vertexCount(); ++v) {
    EXPECT_EQ(result[0].ambientOcclusion[v], 1.0f) << "vertex " << v;
    // The re-drawn horizon directions are not symmetric about the normal (the one-ring of a UV
    // sphere is not), which tilts the bent normal by up to ~0.008 at this tessellation.
    EXPECT_LT(glm::distance(result[0].bentNormals[v], meshes[0].normals[v]), 0.01f) << "vertex " << v;
    // The mean of cosine-distributed directions has length E[cos theta] = 2/3, a little more here
    // because the re-drawn horizon directions are missing.
    EXPECT_NEAR(result[0].bentNormalLengths[v], 2.0f / 3.0f, 0.02f) << "vertex " << v;
  }
}

TEST(VertexVisibility, FloorVertexAtAWallSeesHalfTheCosineWeightedHemisphere) {
  const auto result = bakeVertexVisibility(floorAtWall(), withRays(4096));
  // The wall blocks every direction with x < 0: by symmetry half of the cosine-weighted measure.
  EXPECT_NEAR(result[0].ambientOcclusion[0], 0.5f, 0.01f);
  // Mean escaping direction: (E[x; x > 0], E[y; x > 0], 0) / (1/2) under the density cos/pi, with
  // E[x; x > 0] = 2 / (3 pi) and E[y; x > 0] = 1/3, i.e. (4 / (3 pi), 2/3, 0).
  const glm::vec3 mean(4.0f / (3.0f * glm::pi<float>()), 2.0f / 3.0f, 0.0f);
  EXPECT_LT(glm::distance(result[0].bentNormals[0], glm::normalize(mean)), 0.01f);
  EXPECT_NEAR(result[0].bentNormalLengths[0], glm::length(mean), 0.01f);
}

TEST(VertexVisibility, MaximumDistanceIgnoresFartherOccluders) {
  VisibilitySettings settings = withRays(256);
  settings.maxDistance = 5e-4f;  // the wall is at least 1e-3 away from the floor vertex
  EXPECT_EQ(bakeVertexVisibility(floorAtWall(), settings)[0].ambientOcclusion[0], 1.0f);
  settings.maxDistance = 0.1f;
  EXPECT_NEAR(bakeVertexVisibility(floorAtWall(), settings)[0].ambientOcclusion[0], 0.5f, 0.02f);
}

TEST(VertexVisibility, UnoccludedTransferIsTheClampedCosineConvolution) {
  // A lone square tilted so its normal is a generic direction: no coefficient vanishes by symmetry.
  Mesh quad = toMesh(plane(glm::vec3(0.0f), 2.0f), "quad");
  transformMesh(quad, glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1.0f, 0.2f, -0.6f))));
  const glm::vec3 n = quad.normals[2];
  const auto result = bakeVertexVisibility({quad}, withRays(4096));
  // integral of Y_k(w) max(0, n.w) dw = A_l Y_k(n) (Ramamoorthi and Hanrahan 2001, eq. 8).
  const ShBasis9 basis = shBasis9(n);
  for (int k = 0; k < kShCoefficients; ++k) {
    const int band = k == 0 ? 0 : (k < 4 ? 1 : 2);
    EXPECT_NEAR(result[0].transfer[2][k], shCosineLobeBand(band) * basis[k], 5e-3f) << "k = " << k;
  }
  EXPECT_EQ(result[0].ambientOcclusion[2], 1.0f);
  // A flat one-ring rejects nothing: the bent normal is the normal up to the quadrature error.
  EXPECT_LT(glm::distance(result[0].bentNormals[2], n), 2e-3f);
}

TEST(VertexVisibility, ShadowedTransferOfTheFloorAtTheWallLosesTheWallSide) {
  const auto result = bakeVertexVisibility(floorAtWall(), withRays(4096));
  const ShBasis9& t = result[0].transfer[0];
  // Integrals over the quarter sphere x > 0, y > 0 with weight y (shBasis9: Y1 = c y, Y3 = c x,
  // c = sqrt(3 / (4 pi))): t0 = Y0 pi / 2 (half the unshadowed pi Y0), t1 = c pi / 3 (half the
  // unshadowed 2pi/3 c), t3 = c * integral of x y = c 2/3.
  const float c = std::sqrt(3.0f / (4.0f * glm::pi<float>()));
  EXPECT_NEAR(t[0], 0.5f * glm::pi<float>() * 0.5f / std::sqrt(glm::pi<float>()), 5e-3f);
  EXPECT_NEAR(t[1], c * glm::pi<float>() / 3.0f, 5e-3f);
  EXPECT_NEAR(t[3], c * 2.0f / 3.0f, 5e-3f);
}

TEST(VertexVisibility, SphereOnTheGroundDarkensTheContactRegion) {
  const std::vector<Mesh> meshes = {toMesh(uvSphere(glm::vec3(0.0f, 1.05f, 0.0f), 1.0f, 16, 32), "sphere"),
                                    groundGrid(10.0f, 40)};
  const auto result = bakeVertexVisibility(meshes, withRays(256));
  const std::size_t top = 0, bottom = meshes[0].vertexCount() - 1;  // uvSphere's poles
  ASSERT_LT(glm::distance(meshes[0].positions[bottom], glm::vec3(0.0f, 0.05f, 0.0f)), 1e-6f);
  EXPECT_EQ(result[0].ambientOcclusion[top], 1.0f);
  // The bottom pole looks straight down at the ground 0.05 below: only grazing rays pass its edge.
  EXPECT_LT(result[0].ambientOcclusion[bottom], 0.01f);
  const std::size_t near = closestVertex(meshes[1], glm::vec3(0.5f, 0.0f, 0.0f));
  const std::size_t far = closestVertex(meshes[1], glm::vec3(5.0f, 0.0f, 0.0f));
  EXPECT_LT(result[1].ambientOcclusion[near], 0.7f);
  EXPECT_GT(result[1].ambientOcclusion[far], 0.95f);
  EXPECT_LT(result[1].ambientOcclusion[near], result[1].ambientOcclusion[far]);
  // Near the sphere the open sky lies away from it: the bent normal tilts towards +X.
  EXPECT_GT(result[1].bentNormals[near].x, 0.2f);
}

// The sphere on the ground above and a wrinkled sphere beside it (nine creases round it), moved
// 3,000 units from the origin or shrunk 1,000 times: the vertices' AO is what it is where the meshes
// stand, with vertex and area origins. The rays leave each vertex or point by its own rounding
// (surfaceErrorBound, raytrace/ray_offset.h): the wrinkled sphere's mean difference 0.0018 and 0.0007
// at 3,000 units (2 and 0 of its 1,106 vertices off by more than 0.05), 0 shrunk. The 256-ulp
// offset moved them 0.06 units at 3,000 (mean 0.028 and 0.038, 112 and 165 vertices off) and the
// fixed 2^-16 near the origin was a percent of the shrunk meshes (mean 0.011 and 0.010, 13 and 48).
TEST(VertexVisibility, AoDoesNotDependOnWhereTheMeshStandsOrItsSize) {
  Mesh wrinkled = toMesh(uvSphere(glm::vec3(2.5f, 1.0f, 0.0f), 1.0f, 24, 48), "wrinkled");
  for (std::size_t v = 0; v < wrinkled.vertexCount(); ++v) {
    const glm::vec3 d = wrinkled.positions[v] - glm::vec3(2.5f, 1.0f, 0.0f);
    wrinkled.positions[v] = glm::vec3(2.5f, 1.0f, 0.0f) + d * (1.0f + 0.15f * std::sin(9.0f * std::atan2(d.z, d.x)));
  }
  wrinkled.normals = angleWeightedNormals(wrinkled.positions, wrinkled.indices);
  const std::vector<Mesh> original = {toMesh(uvSphere(glm::vec3(0.0f, 1.05f, 0.0f), 1.0f, 16, 32), "sphere"),
                                      wrinkled, groundGrid(10.0f, 40)};
  for (const bool area : {false, true}) {
    VisibilitySettings settings = withRays(256);
    settings.areaSampling = area;
    const auto here = bakeVertexVisibility(original, settings);
    const auto moved = [&](float scale, glm::vec3 shift) {
      std::vector<Mesh> meshes = original;
      for (Mesh& mesh : meshes)
        for (glm::vec3& p : mesh.positions) p = scale * p + shift;
      return bakeVertexVisibility(meshes, settings);
    };
    for (const auto& [scale, shift] : {std::pair{1.0f, glm::vec3(3000.0f, 0.0f, -3000.0f)}, std::pair{1e-3f, glm::vec3(0.0f)}}) {
      const auto there = moved(scale, shift);
      for (std::size_t m = 0; m < original.size(); ++m) {
        double sum = 0.0;
        std::size_t off = 0;
        for (std::size_t v = 0; v < original[m].vertexCount(); ++v) {
          const float difference = std::abs(there[m].ambientOcclusion[v] - here[m].ambientOcclusion[v]);
          sum += difference;
          off += difference > 0.05f;
        }
        const double mean = sum / double(original[m].vertexCount());
        const std::string where = original[m].name + (area ? ", area origins" : ", vertex origins") + ", scale " +
                                  std::to_string(scale) + ", shifted " + std::to_string(shift.x);
        EXPECT_LT(mean, 0.005) << where;
        // A crease vertex 3,000 units out may change: its triangles' corners are rounded to 2.4e-4.
        EXPECT_LE(off, original[m].vertexCount() / 200) << where;
      }
    }
  }
}

TEST(VertexVisibility, SameSeedIsBitIdenticalAndAnotherSeedDiffers) {
  const std::vector<Mesh> meshes = {toMesh(uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 8, 16), "sphere"),
                                    groundGrid(3.0f, 12)};
  const auto first = bakeVertexVisibility(meshes, withRays(64, 7));
  const auto second = bakeVertexVisibility(meshes, withRays(64, 7));
  const auto other = bakeVertexVisibility(meshes, withRays(64, 8));
  bool anyDifferent = false;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::size_t n = meshes[m].vertexCount();
    EXPECT_EQ(
        std::memcmp(first[m].ambientOcclusion.data(), second[m].ambientOcclusion.data(), n * sizeof(float)),
        0);
    EXPECT_EQ(std::memcmp(first[m].bentNormals.data(), second[m].bentNormals.data(), n * sizeof(glm::vec3)),
              0);
    EXPECT_EQ(std::memcmp(first[m].transfer.data(), second[m].transfer.data(), n * sizeof(ShBasis9)), 0);
    anyDifferent = anyDifferent || first[m].ambientOcclusion != other[m].ambientOcclusion;
  }
  EXPECT_TRUE(anyDifferent);
}

TEST(VertexVisibility, FullyEnclosedVertexKeepsItsNormalAndZeroLength) {
  // A floor vertex inside a closed box: every ray hits the box.
  std::vector<Mesh> meshes = {groundGrid(0.5f, 2), toMesh(box(glm::vec3(0.0f), glm::vec3(4.0f)), "box")};
  const auto result = bakeVertexVisibility(meshes, withRays(64));
  const std::size_t centre = closestVertex(meshes[0], glm::vec3(0.0f));
  EXPECT_EQ(result[0].ambientOcclusion[centre], 0.0f);
  EXPECT_EQ(result[0].bentNormals[centre], glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(result[0].bentNormalLengths[centre], 0.0f);
  for (float t : result[0].transfer[centre]) EXPECT_EQ(t, 0.0f);
}

TEST(VertexVisibility, BadSettingsAndMeshesAreErrors) {
  const std::vector<Mesh> meshes = floorAtWall();
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, withRays(0)); }),
            "vertex visibility: ray count 0 is not in 1..16777216");
  VisibilitySettings settings = withRays(16);
  settings.maxDistance = -1.0f;
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(meshes, settings); }),
            "vertex visibility: maximum distance must be finite and >= 0 (0 = infinite)");
  std::vector<Mesh> noNormals = meshes;
  noNormals[1].normals.clear();
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(noNormals, withRays(16)); }),
            "vertex visibility: mesh 1 has 0 normals for 24 vertices");
  std::vector<Mesh> nan = meshes;
  nan[0].positions[3].y = std::nanf("");
  EXPECT_EQ(test::errorMessage([&] { bakeVertexVisibility(nan, withRays(16)); }),
            "ray scene mesh 0: vertex 3 has a non-finite position");
}

}  // namespace
}  // namespace iblkit
