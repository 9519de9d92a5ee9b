#include "core/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "support/gltf_builder.h"

namespace iblkit {
namespace {

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-6f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(Bounds, EmptyUntilExtended) {
  Bounds b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.radius(), 0.0f);
  EXPECT_EQ(b.center(), glm::vec3(0.0f));
  b.extend(glm::vec3(1.0f, 2.0f, 3.0f));
  b.extend(glm::vec3(-1.0f, 0.0f, 3.0f));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.min, glm::vec3(-1.0f, 0.0f, 3.0f));
  EXPECT_EQ(b.max, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(b.center(), glm::vec3(0.0f, 1.0f, 3.0f));
  EXPECT_FLOAT_EQ(b.radius(), std::sqrt(2.0f));
  EXPECT_EQ(b.corners()[0], b.min);
  EXPECT_EQ(b.corners()[7], b.max);
  EXPECT_EQ(b.corners()[1], glm::vec3(1.0f, 0.0f, 3.0f));  // bit 0 picks max.x

  Bounds merged;
  merged.extend(Bounds());  // an empty box adds nothing
  EXPECT_TRUE(merged.empty());
  merged.extend(b);
  EXPECT_EQ(merged.min, b.min);
  EXPECT_EQ(merged.max, b.max);
}

TEST(AngleWeightedNormals, CubeCornerIsTheDiagonal) {
  const test::CubeGeometry cube = test::unitCube();
  const std::vector<glm::vec3> normals = angleWeightedNormals(cube.positions, cube.indices);
  ASSERT_EQ(normals.size(), 8u);
  // Three faces meet at each corner with 90 degrees each, however the faces are split.
  for (std::size_t i = 0; i < 8; ++i)
    expectNear(normals[i], glm::normalize(2.0f * cube.positions[i] - glm::vec3(1.0f)));
}

TEST(AngleWeightedNormals, IndependentOfTessellation) {
  // Two perpendicular faces meeting at the origin: the +Z face as one triangle with a 90 degree
  // corner, the +X face as three 30 degree triangles. Angle weighting sees 90 degrees of each
  // (normalize(1, 0, 1)); weighting by triangle count would lean towards +X.
  std::vector<glm::vec3> positions = {glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  std::vector<std::uint32_t> indices = {0, 1, 2};
  for (int k = 0; k <= 3; ++k) {
    const float a = glm::radians(30.0f * float(k));
    positions.emplace_back(0.0f, std::cos(a), std::sin(a));  // in the x = 0 plane, from +Y to +Z
  }
  for (std::uint32_t k = 0; k < 3; ++k) indices.insert(indices.end(), {0, 3 + k, 4 + k});
  const std::vector<glm::vec3> normals = angleWeightedNormals(positions, indices);
  expectNear(normals[0], glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f)));
}

TEST(AngleWeightedNormals, UnusedVertexGetsUp) {
  const std::vector<glm::vec3> positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                                            glm::vec3(5, 5, 5)};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  const std::vector<glm::vec3> normals = angleWeightedNormals(positions, indices);
  expectNear(normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(normals[3], glm::vec3(0, 1, 0));
}

TEST(RepairNormals, ReplacesOnlyBadNormals) {
  const test::CubeGeometry cube = test::unitCube();
  Mesh mesh;
  mesh.positions = cube.positions;
  mesh.indices = cube.indices;
  EXPECT_EQ(repairNormals(mesh), 8u);  // none: all generated
  ASSERT_EQ(mesh.normals.size(), 8u);

  const glm::vec3 kept(0.0f, 0.0f, 1.0f);
  mesh.normals.assign(8, kept);
  mesh.normals[0] = glm::vec3(0.0f);
  mesh.normals[7] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(repairNormals(mesh), 2u);
  expectNear(mesh.normals[0], glm::normalize(glm::vec3(-1.0f)));
  expectNear(mesh.normals[7], glm::normalize(glm::vec3(1.0f)));
  EXPECT_EQ(mesh.normals[3], kept);
  EXPECT_EQ(repairNormals(mesh), 0u);
}

TEST(RemoveZeroAreaTriangles, DropsOnlyDegenerateOnesAndKeepsVertices) {
  Mesh mesh;
  mesh.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(2, 0, 0)};
  mesh.indices = {0, 1, 2,   // kept
                  0, 0, 2,   // repeated corner
                  0, 1, 3,   // collinear
                  2, 1, 0};  // kept (back-facing is fine)
  EXPECT_EQ(removeZeroAreaTriangles(mesh), 2u);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 0}));
  EXPECT_EQ(mesh.positions.size(), 4u);
}

TEST(TransformMesh, NormalsFollowTheInverseTranspose) {
  Mesh mesh;
  mesh.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  mesh.normals = {glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(0, 0, 1), glm::vec3(1, 0, 0)};
  mesh.indices = {0, 1, 2};
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  m = glm::rotate(m, glm::radians(30.0f), glm::vec3(0, 1, 0));
  m = glm::scale(m, glm::vec3(2.0f, 1.0f, 0.5f));
  const Mesh original = mesh;
  transformMesh(mesh, m);
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
  for (std::size_t i = 0; i < 3; ++i) {
    expectNear(mesh.positions[i], glm::vec3(m * glm::vec4(original.positions[i], 1.0f)), 1e-5f);
    expectNear(mesh.normals[i], glm::normalize(normalMatrix * original.normals[i]), 1e-5f);
  }
  EXPECT_EQ(mesh.indices, original.indices);
}

TEST(TransformMesh, MirrorFlipsWindingAndKeepsNormalsOutward) {
  Mesh mesh;
  mesh.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  mesh.normals.assign(3, glm::normalize(glm::vec3(1, 0, 1)));
  mesh.indices = {0, 1, 2};
  transformMesh(mesh, glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)));
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 2, 1}));
  expectNear(mesh.normals[0], glm::normalize(glm::vec3(-1, 0, 1)));
  // The front face (counter-clockwise) still faces where the normals point.
  const glm::vec3 geometric = glm::cross(mesh.positions[mesh.indices[1]] - mesh.positions[mesh.indices[0]],
                                         mesh.positions[mesh.indices[2]] - mesh.positions[mesh.indices[0]]);
  EXPECT_GT(glm::dot(geometric, mesh.normals[0]), 0.0f);
}

// A triangle in z = 0 with tangents along +x and w = +1 (bitangent +y), and a second uv set.
Mesh tangentTriangle() {
  Mesh mesh;
  mesh.positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  mesh.normals.assign(3, glm::vec3(0, 0, 1));
  mesh.tangents.assign(3, glm::vec4(1, 0, 0, 1));
  mesh.texcoords = {glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(0, 0)};
  mesh.texcoords1 = {glm::vec2(0.1f, 0.2f), glm::vec2(0.3f, 0.4f), glm::vec2(0.5f, 0.6f)};
  mesh.indices = {0, 1, 2};
  return mesh;
}

TEST(TransformMesh, TangentsFollowTheSurfaceAndStayOrthogonal) {
  Mesh mesh = tangentTriangle();
  mesh.normals.assign(3, glm::normalize(glm::vec3(0, 1, 1)));  // a tangent frame that a shear moves
  mesh.tangents.assign(3, glm::vec4(1, 0, 0, 1));
  glm::mat4 m = glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(0, 0, 1));
  m = glm::scale(m, glm::vec3(1.0f, 3.0f, 0.5f));
  const Mesh original = mesh;
  transformMesh(mesh, m);
  ASSERT_EQ(mesh.tangents.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::vec3 t(mesh.tangents[i]);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, mesh.normals[i]), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(t, glm::normalize(glm::mat3(m) * glm::vec3(original.tangents[i]))), 0.99f);
    EXPECT_EQ(mesh.tangents[i].w, 1.0f);
  }
  EXPECT_EQ(mesh.texcoords1, original.texcoords1);
  EXPECT_EQ(mesh.texcoords, original.texcoords);
}

TEST(TransformMesh, MirrorFlipsTangentHandednessSoTheBitangentFollows) {
  Mesh mesh = tangentTriangle();
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  const glm::vec3 bitangentBefore = mesh.tangents[0].w * glm::cross(mesh.normals[0], glm::vec3(mesh.tangents[0]));
  transformMesh(mesh, mirror);
  expectNear(glm::vec3(mesh.tangents[0]), glm::vec3(-1, 0, 0));
  EXPECT_EQ(mesh.tangents[0].w, -1.0f);
  // The bitangent (the uv set's "up the image") is the mirrored bitangent.
  const glm::vec3 bitangentAfter = mesh.tangents[0].w * glm::cross(mesh.normals[0], glm::vec3(mesh.tangents[0]));
  expectNear(bitangentAfter, glm::mat3(mirror) * bitangentBefore);
}

}  // namespace
}  // namespace iblkit
