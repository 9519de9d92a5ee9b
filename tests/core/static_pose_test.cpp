#include "core/static_pose.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/procedural_mesh.h"

namespace iblkit {
namespace {

// A small UV sphere with tangents, as the loader's meshes come.
Mesh sphere() {
  Mesh mesh = toMesh(uvSphere(glm::vec3(0.2f, -0.1f, 0.3f), 0.8f, 5, 7), "sphere", 0);
  for (const glm::vec3& n : mesh.normals)
    mesh.tangents.emplace_back(glm::normalize(glm::cross(glm::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), n)),
                               1.0f);
  return mesh;
}

void expectSameMesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_LT(glm::distance(a.positions[i], b.positions[i]), 1e-5f) << i;
    EXPECT_LT(glm::distance(a.normals[i], b.normals[i]), 1e-5f) << i;
    EXPECT_LT(glm::distance(a.tangents[i], b.tangents[i]), 1e-5f) << i;
  }
  EXPECT_EQ(a.indices, b.indices);
}

// One matrix for every vertex is transformMesh, a mirroring one included (normals by the cofactor,
// tangents' handedness and the winding flipped).
TEST(StaticPose, PerVertexTransformWithOneMatrixIsTransformMesh) {
  const glm::mat4 turnAndStretch = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), 0.7f,
                                                          glm::normalize(glm::vec3(1, 1, 0))),
                                              glm::vec3(2.0f, 0.5f, 1.5f));
  for (const glm::mat4& m : {turnAndStretch, glm::scale(turnAndStretch, glm::vec3(-1, 1, 1))}) {
    Mesh expected = sphere(), actual = sphere();
    transformMesh(expected, m);
    const std::vector<glm::mat4> matrices(actual.vertexCount(), m);
    transformMeshPerVertex(actual, matrices);
    expectSameMesh(actual, expected);
  }
}

// Weights are divided by their sum; a vertex without weight keeps the identity.
TEST(StaticPose, SkinningMatricesBlendTheJointsByNormalisedWeights) {
  const glm::mat4 a = glm::translate(glm::mat4(1.0f), glm::vec3(4, 0, 0));
  const glm::mat4 b = glm::scale(glm::mat4(1.0f), glm::vec3(3.0f));
  std::vector<VertexInfluences> influences(3);
  influences[0].joints = {1, 0, 0, 0, 0, 0, 0, 0};
  influences[0].weights = {1, 0, 0, 0, 0, 0, 0, 0};
  influences[1].joints = {0, 0, 0, 0, 0, 0, 0, 1};  // the second set's last slot
  influences[1].weights = {3, 0, 0, 0, 0, 0, 0, 1};
  const std::vector<glm::mat4> m = skinningMatrices(influences, std::vector<glm::mat4>{a, b});
  EXPECT_EQ(m[0], b);
  EXPECT_EQ(m[1], 0.75f * a + 0.25f * b);
  EXPECT_EQ(m[2], glm::mat4(1.0f));
}

TEST(StaticPose, MorphTargetsAddTheirWeightedDisplacements) {
  Mesh mesh = sphere();
  const Mesh original = mesh;
  MorphTarget up, out;
  up.positions.assign(mesh.vertexCount(), glm::vec3(0, 1, 0));
  out.normals.assign(mesh.vertexCount(), glm::vec3(0.5f, 0, 0));
  const std::vector<MorphTarget> targets = {up, out};
  applyMorphTargets(mesh, targets, std::vector<float>{0.25f, 2.0f});
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    EXPECT_EQ(mesh.positions[i], original.positions[i] + glm::vec3(0, 0.25f, 0));
    EXPECT_EQ(mesh.normals[i], original.normals[i] + glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.tangents[i], original.tangents[i]);
  }
  applyMorphTargets(mesh, targets, std::vector<float>{});  // no weights: nothing
  EXPECT_EQ(mesh.positions[0], original.positions[0] + glm::vec3(0, 0.25f, 0));
}

}  // namespace
}  // namespace iblkit
