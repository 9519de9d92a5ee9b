// The baker's per-vertex ambient occlusion against the reference tracer's per-point estimate
// (reference/ambient_occlusion.h, what `iblkit-trace --integrator ao` averages per pixel),
// computed at the same vertices with the same number of rays: two programs, one quantity.
//
// The reference uses independent uniform random numbers, so its estimate at a vertex with true
// AO p has variance p(1 - p) / N. The baker uses an Owen-scrambled (0,2)-net, whose variance is at
// most b/(b-1) = 2 times the Monte Carlo variance for any square-integrable integrand (Owen 1997,
// "Monte Carlo variance of scrambled net quadrature", theorem 1 with s = 2, b = 2). So the
// difference has a standard error of at most sqrt(3 p(1 - p) / N).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "baker/vertex_visibility.h"
#include "core/procedural_mesh.h"
#include "core/rng.h"
#include "raytrace/ray_scene.h"
#include "reference/ambient_occlusion.h"

namespace iblkit {
namespace {

constexpr int kRays = 256;

// A square of side 2 * halfSize in the plane y = 0 facing +Y, cut into cells x cells squares.
Mesh groundGrid(float halfSize, int cells) {
  return toMesh(gridPlane(glm::vec3(0.0f), 2.0f * halfSize, cells), "ground");
}

// A sphere just above a ground grid (partly occluded vertices on both), and a box standing on the
// ground beside it (flat faces, hard edges).
std::vector<Mesh> testScene() {
  return {toMesh(uvSphere(glm::vec3(0.0f, 1.02f, 0.0f), 1.0f, 16, 32), "sphere"),
          toMesh(box(glm::vec3(1.6f, 0.5f, 0.3f), glm::vec3(0.6f, 1.0f, 0.8f)), "box"), groundGrid(3.0f, 24)};
}

// The reference's AO at every vertex: kRays samples of sampleAmbientOcclusion with PCG32 numbers,
// the vertex normal as both the geometric and the shading normal.
std::vector<std::vector<float>> referenceAo(const std::vector<Mesh>& meshes, float maxDistance) {
  RayScene rays;
  for (const Mesh& mesh : meshes) rays.addTriangleMesh(mesh.positions, mesh.indices);
  rays.commit();
  std::vector<std::vector<float>> ao(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    for (std::size_t v = 0; v < meshes[m].vertexCount(); ++v) {
      PCG32 rng(1234 + m, v);
      int escaped = 0;
      for (int i = 0; i < kRays; ++i)
        escaped += sampleAmbientOcclusion(rays, meshes[m].positions[v], nullptr, meshes[m].normals[v],
                                          meshes[m].normals[v], rng.uniform2D(), maxDistance)
                       .escaped;
      ao[m].push_back(float(escaped) / float(kRays));
    }
  }
  return ao;
}

struct Comparison {
  std::size_t vertices = 0, partlyOccluded = 0, outliers = 0, contacts = 0;
  double meanDifference = 0.0, meanDifferenceLimit = 0.0;
};

// The box's side-face vertices on the ground's plane (y = 0): a point on two surfaces at once.
// From the vertex itself an upward ray meets the ground at t ~ 0, so the reference's AO there is
// 0; the baker takes the side of the face the vertex stands for (vertexRayOrigin), where a side
// face sees half the sky (VisibilityPointSampling.AContactVertexSeesWhatItsFaceSees). Not compared.
bool onTheGroundsPlane(const Mesh& mesh, std::size_t v) {
  return mesh.name == "box" && mesh.positions[v].y == 0.0f && std::abs(mesh.normals[v].y) < 0.5f;
}

// Per vertex: |baker - reference| <= 5 standard errors + 1/N (one ray's worth, for p near 0 or
// 1 where the normal approximation fails). Over all vertices: the mean difference (a bias
// common to all vertices, such as a ray offset or hemisphere convention that differs) within 4
// standard errors of the mean.
Comparison compare(const std::vector<Mesh>& meshes, const std::vector<MeshVisibility>& baked,
                   const std::vector<std::vector<float>>& reference) {
  Comparison c;
  double sumDifference = 0.0, sumVariance = 0.0;
  for (std::size_t m = 0; m < baked.size(); ++m)
    for (std::size_t v = 0; v < baked[m].ambientOcclusion.size(); ++v) {
      if (onTheGroundsPlane(meshes[m], v)) {
        ++c.contacts;
        continue;
      }
      const double a = baked[m].ambientOcclusion[v], b = reference[m][v], p = 0.5 * (a + b);
      const double variance = 3.0 * p * (1.0 - p) / kRays;
      ++c.vertices;
      c.partlyOccluded += p > 0.05 && p < 0.95;
      if (std::abs(a - b) > 5.0 * std::sqrt(variance) + 1.0 / kRays) ++c.outliers;
      sumDifference += a - b;
      sumVariance += variance;
    }
  c.meanDifference = sumDifference / double(c.vertices);
  c.meanDifferenceLimit = 4.0 * std::sqrt(sumVariance) / double(c.vertices) + 1e-4;
  return c;
}

VisibilitySettings bakeSettings(float maxDistance) {
  VisibilitySettings settings;
  settings.rayCount = kRays;
  settings.maxDistance = maxDistance;
  return settings;
}

TEST(VertexAoReference, BakerMatchesTheReferenceTracersAoAtTheVertices) {
  const std::vector<Mesh> meshes = testScene();
  const std::vector<MeshVisibility> baked = bakeVertexVisibility(meshes, bakeSettings(0.0f));
  const Comparison c = compare(meshes, baked, referenceAo(meshes, std::numeric_limits<float>::infinity()));
  // The scene must test something: many vertices neither fully open nor fully closed.
  EXPECT_GT(c.partlyOccluded, 150u);
  // The 4 side faces' 2 bottom vertices each, left out of the comparison: there the baker sees
  // what the face just above the ground sees, at most half the sky (the face towards the sphere
  // sees it too: 0.21 and 0.29 there), not the 0 of a point on the ground.
  EXPECT_EQ(c.contacts, 8u);
  for (std::size_t v = 0; v < meshes[1].vertexCount(); ++v)
    if (onTheGroundsPlane(meshes[1], v)) {
      EXPECT_GT(baked[1].ambientOcclusion[v], 0.15f) << v;
      EXPECT_LT(baked[1].ambientOcclusion[v], 0.55f) << v;
    }
  EXPECT_EQ(c.outliers, 0u) << "of " << c.vertices << " vertices";
  EXPECT_LE(std::abs(c.meanDifference), c.meanDifferenceLimit);
}

TEST(VertexAoReference, AgreesWithAMaximumDistanceToo) {
  const std::vector<Mesh> meshes = testScene();
  const Comparison c = compare(meshes, bakeVertexVisibility(meshes, bakeSettings(0.5f)), referenceAo(meshes, 0.5f));
  EXPECT_EQ(c.contacts, 8u);
  EXPECT_GT(c.partlyOccluded, 100u);
  EXPECT_EQ(c.outliers, 0u) << "of " << c.vertices << " vertices";
  EXPECT_LE(std::abs(c.meanDifference), c.meanDifferenceLimit);
}

// The comparison can fail: a baker that ignores occluders beyond 0.5 is told apart from the
// reference without a limit.
TEST(VertexAoReference, DetectsADifferentMaximumDistance) {
  const std::vector<Mesh> meshes = testScene();
  const Comparison c = compare(meshes, bakeVertexVisibility(meshes, bakeSettings(0.5f)),
                               referenceAo(meshes, std::numeric_limits<float>::infinity()));
  EXPECT_GT(std::abs(c.meanDifference), c.meanDifferenceLimit);
}

}  // namespace
}  // namespace iblkit
