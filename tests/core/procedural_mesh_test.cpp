#include "core/procedural_mesh.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <map>
#include <utility>

#include "core/error.h"

namespace iblkit {
namespace {

glm::vec3 corner(const ProceduralMesh& mesh, std::size_t triangle, int k) {
  return mesh.positions[mesh.indices[3 * triangle + k]];
}

// Signed volume enclosed by a closed mesh (divergence theorem: sum over triangles of
// dot(v0, cross(v1, v2)) / 6); positive when the triangles wind counter-clockwise seen from outside.
double signedVolume(const ProceduralMesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t)
    volume += glm::dot(glm::dvec3(corner(mesh, t, 0)),
                       glm::cross(glm::dvec3(corner(mesh, t, 1)), glm::dvec3(corner(mesh, t, 2)))) /
              6.0;
  return volume;
}

double area(const ProceduralMesh& mesh) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t)
    sum += 0.5 * glm::length(glm::cross(glm::dvec3(corner(mesh, t, 1) - corner(mesh, t, 0)),
                                        glm::dvec3(corner(mesh, t, 2) - corner(mesh, t, 0))));
  return sum;
}

// Every triangle's right-hand normal cross(v1 - v0, v2 - v0) lies on the side of its vertex normals.
void expectWindingAgreesWithNormals(const ProceduralMesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
    const glm::vec3 ng = glm::normalize(
        glm::cross(corner(mesh, t, 1) - corner(mesh, t, 0), corner(mesh, t, 2) - corner(mesh, t, 0)));
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(glm::dot(ng, mesh.normals[mesh.indices[3 * t + k]]), 0.5f) << "triangle " << t;
  }
}

TEST(ProceduralMesh, SphereCountsRadiusAndNormals) {
  const glm::vec3 center(1.0f, -2.0f, 3.0f);
  const ProceduralMesh mesh = uvSphere(center, 2.5f, 5, 7);
  EXPECT_EQ(mesh.positions.size(), 2u + 4u * 7u);
  EXPECT_EQ(mesh.indices.size(), 3u * 2u * 7u * 4u);
  EXPECT_EQ(mesh.positions.front(), center + glm::vec3(0.0f, 2.5f, 0.0f));
  EXPECT_EQ(mesh.positions.back(), center + glm::vec3(0.0f, -2.5f, 0.0f));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_NEAR(glm::distance(mesh.positions[i], center), 2.5f, 1e-5f);
    EXPECT_NEAR(glm::length(mesh.normals[i]), 1.0f, 1e-6f);
    const glm::vec3 expected = (mesh.positions[i] - center) / 2.5f;
    EXPECT_NEAR(glm::distance(mesh.normals[i], expected), 0.0f, 1e-6f);
  }
  for (uint32_t index : mesh.indices) EXPECT_LT(index, mesh.positions.size());
}

TEST(ProceduralMesh, SphereWindsOutwardAndIsClosed) {
  const ProceduralMesh mesh = uvSphere(glm::vec3(0.0f), 1.0f, 6, 9);
  expectWindingAgreesWithNormals(mesh);
  // Closed with consistent orientation: each directed edge occurs once, and its reverse once.
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t)
    for (int k = 0; k < 3; ++k) ++edges[{mesh.indices[3 * t + k], mesh.indices[3 * t + (k + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
  }
}

TEST(ProceduralMesh, FineSphereApproachesAreaAndVolume) {
  const ProceduralMesh mesh = uvSphere(glm::vec3(0.5f), 2.0f, 64, 128);
  // Inscribed polyhedron: slightly less than the sphere, by O(1/rings^2).
  const double sphereArea = 4.0 * glm::pi<double>() * 4.0, sphereVolume = 4.0 / 3.0 * glm::pi<double>() * 8.0;
  EXPECT_LT(area(mesh), sphereArea);
  EXPECT_GT(area(mesh), 0.998 * sphereArea);
  EXPECT_LT(signedVolume(mesh), sphereVolume);
  EXPECT_GT(signedVolume(mesh), 0.997 * sphereVolume);
}

TEST(ProceduralMesh, PlaneFacesUp) {
  const ProceduralMesh mesh = plane(glm::vec3(1.0f, 2.0f, 3.0f), 4.0f);
  ASSERT_EQ(mesh.positions.size(), 4u);
  ASSERT_EQ(mesh.indices.size(), 6u);
  for (const glm::vec3& p : mesh.positions) {
    EXPECT_FLOAT_EQ(p.y, 2.0f);
    EXPECT_FLOAT_EQ(std::abs(p.x - 1.0f), 2.0f);
    EXPECT_FLOAT_EQ(std::abs(p.z - 3.0f), 2.0f);
  }
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0.0f, 1.0f, 0.0f));
  expectWindingAgreesWithNormals(mesh);
  EXPECT_DOUBLE_EQ(area(mesh), 16.0);
}

TEST(ProceduralMesh, GridPlaneFacesUpWithInnerVertices) {
  const ProceduralMesh mesh = gridPlane(glm::vec3(1.0f, 2.0f, 3.0f), 4.0f, 4);
  ASSERT_EQ(mesh.positions.size(), 25u);
  ASSERT_EQ(mesh.indices.size(), 4u * 4u * 6u);
  EXPECT_EQ(mesh.positions[0], glm::vec3(-1.0f, 2.0f, 1.0f));  // row 0 at -Z, from -X
  EXPECT_EQ(mesh.positions[12], glm::vec3(1.0f, 2.0f, 3.0f));  // the centre
  EXPECT_EQ(mesh.positions[24], glm::vec3(3.0f, 2.0f, 5.0f));
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0.0f, 1.0f, 0.0f));
  expectWindingAgreesWithNormals(mesh);
  EXPECT_DOUBLE_EQ(area(mesh), 16.0);
  const Mesh scene = toMesh(mesh, "grid", 3);
  EXPECT_EQ(scene.name, "grid");
  EXPECT_EQ(scene.material, 3);
  EXPECT_EQ(scene.positions, mesh.positions);
  EXPECT_EQ(scene.normals, mesh.normals);
  EXPECT_EQ(scene.indices, mesh.indices);
}

TEST(ProceduralMesh, BoxVolumeAreaAndFaceNormals) {
  const glm::vec3 center(-1.0f, 0.5f, 2.0f), size(1.0f, 2.0f, 4.0f);
  const ProceduralMesh mesh = box(center, size);
  ASSERT_EQ(mesh.positions.size(), 24u);
  ASSERT_EQ(mesh.indices.size(), 36u);
  expectWindingAgreesWithNormals(mesh);
  EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-5);
  EXPECT_NEAR(area(mesh), 2.0 * (2.0 + 4.0 + 8.0), 1e-5);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    // Each vertex lies on the face its normal names: offset from the centre along n is half the size.
    const glm::vec3 n = mesh.normals[i];
    EXPECT_FLOAT_EQ(glm::dot(mesh.positions[i] - center, n), 0.5f * glm::dot(size, glm::abs(n)));
  }
}

TEST(ProceduralMesh, BadParametersThrow) {
  const auto expectError = [](auto&& make, const char* message) {
    try {
      make();
      ADD_FAILURE() << "no error for: " << message;
    } catch (const Error& e) {
      EXPECT_STREQ(e.what(), message);
    }
  };
  expectError([] { uvSphere(glm::vec3(0.0f), 1.0f, 1, 8); }, "uvSphere: rings must be at least 2 (got 1)");
  expectError([] { uvSphere(glm::vec3(0.0f), 1.0f, 4, 2); }, "uvSphere: segments must be at least 3 (got 2)");
  expectError([] { uvSphere(glm::vec3(0.0f), -1.0f, 4, 8); },
              "uvSphere: radius must be positive and finite (got -1)");
  expectError([] { plane(glm::vec3(0.0f, NAN, 0.0f), 1.0f); }, "plane: center is not finite");
  expectError([] { box(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 1.0f)); },
              "box: size.y must be positive and finite (got 0)");
}

}  // namespace
}  // namespace iblkit
