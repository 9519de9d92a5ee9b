#include "core/tangent_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace iblkit {
namespace {

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

glm::vec3 bitangent(const Mesh& mesh, std::size_t v) {
  return mesh.tangents[v].w * glm::cross(mesh.normals[v], glm::vec3(mesh.tangents[v]));
}

// A quad in z = 0 from (x0, 0) to (x0 + 1, 1), its image upright (glTF uv: v = 1 - y), u running
// from u0 at x0 to u1 at x0 + 1.
void addQuad(Mesh& mesh, float x0, float u0, float u1) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0 + 1, 1, 0}, {x0, 1, 0}});
  mesh.normals.insert(mesh.normals.end(), 4, glm::vec3(0, 0, 1));
  mesh.texcoords.insert(mesh.texcoords.end(), {{u0, 1}, {u1, 1}, {u1, 0}, {u0, 0}});
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

TEST(GenerateTangents, UvMappedPlaneGetsTangentsAlongPlusU) {
  Mesh mesh;
  addQuad(mesh, 0.0f, 0.0f, 1.0f);
  ASSERT_EQ(generateTangents(mesh), 4u);
  ASSERT_EQ(mesh.tangents.size(), 4u);
  for (std::size_t v = 0; v < 4; ++v) {
    expectNear(glm::vec3(mesh.tangents[v]), glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.tangents[v].w, 1.0f);
    expectNear(bitangent(mesh, v), glm::vec3(0, 1, 0));  // up the image: -v
  }
}

TEST(GenerateTangents, MirroredUvsGetNegativeHandedness) {
  // Two quads side by side; the right one mirrors u (1 at the seam back to 0), as modellers do
  // for symmetric halves sharing one texture.
  Mesh mesh;
  addQuad(mesh, 0.0f, 0.0f, 1.0f);
  addQuad(mesh, 1.0f, 1.0f, 0.0f);
  ASSERT_EQ(generateTangents(mesh), 8u);
  for (std::size_t v : {0u, 3u}) {  // left edge
    expectNear(glm::vec3(mesh.tangents[v]), glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.tangents[v].w, 1.0f);
  }
  for (std::size_t v : {5u, 6u}) {  // right edge of the mirrored half: +u is -x there
    expectNear(glm::vec3(mesh.tangents[v]), glm::vec3(-1, 0, 0));
    EXPECT_EQ(mesh.tangents[v].w, -1.0f);
  }
  // Both halves' bitangents still point up the image (v is not mirrored).
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_TRUE(mesh.tangents[v].w == 1.0f || mesh.tangents[v].w == -1.0f);
    expectNear(bitangent(mesh, v), glm::vec3(0, 1, 0));
  }
}

TEST(GenerateTangents, SphereTangentsAreUnitAndOrthogonalToNormals) {
  // A latitude-longitude sphere, u along longitude (east), v down from the north pole.
  const int rings = 12, segments = 24;
  Mesh mesh;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      const float theta = std::numbers::pi_v<float> * r / rings, phi = 2.0f * std::numbers::pi_v<float> * s / segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(n);
      mesh.normals.push_back(n);
      mesh.texcoords.emplace_back(static_cast<float>(s) / segments, static_cast<float>(r) / rings);
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  generateTangents(mesh);
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec3 t(mesh.tangents[v]);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << v;
    EXPECT_NEAR(glm::dot(t, mesh.normals[v]), 0.0f, 1e-5f) << v;
    const glm::vec3 p = mesh.positions[v];
    if (std::abs(p.y) < 0.9f) {
      // Away from the poles: +u is dp/dphi, along (z, 0, -x); the image's up (-v) is north.
      EXPECT_GT(glm::dot(t, glm::normalize(glm::vec3(p.z, 0.0f, -p.x))), 0.99f) << v;
      EXPECT_EQ(mesh.tangents[v].w, 1.0f) << v;
      EXPECT_GT(bitangent(mesh, v).y, 0.0f) << v;
    }
  }
}

TEST(GenerateTangents, DegenerateUvsGiveAFiniteTangent) {
  Mesh mesh;
  addQuad(mesh, 0.0f, 0.0f, 1.0f);
  mesh.texcoords.assign(4, glm::vec2(0.5f));  // every triangle has zero uv area
  mesh.normals.assign(4, glm::normalize(glm::vec3(1, 2, 3)));
  ASSERT_EQ(generateTangents(mesh), 4u);
  for (const glm::vec4& t : mesh.tangents) {
    EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(t), mesh.normals[0]), 0.0f, 1e-5f);
    EXPECT_EQ(t.w, 1.0f);
  }
}

TEST(GenerateTangents, UsesTheNamedUvSetAndKeepsExistingTangents) {
  Mesh mesh;
  addQuad(mesh, 0.0f, 0.0f, 1.0f);
  mesh.texcoords1 = mesh.texcoords;
  for (glm::vec2& uv : mesh.texcoords1) uv = glm::vec2(uv.y, uv.x);  // set 1: u along -y
  EXPECT_EQ(generateTangents(mesh, 1), 4u);
  expectNear(glm::vec3(mesh.tangents[0]), glm::vec3(0, -1, 0));
  // Tangents already there are kept.
  const std::vector<glm::vec4> kept = mesh.tangents;
  EXPECT_EQ(generateTangents(mesh, 0), 0u);
  EXPECT_EQ(mesh.tangents, kept);
  // No such uv set: nothing.
  Mesh bare;
  addQuad(bare, 0.0f, 0.0f, 1.0f);
  EXPECT_EQ(generateTangents(bare, 1), 0u);
  EXPECT_TRUE(bare.tangents.empty());
}

TEST(GenerateTangents, RepeatedVerticesAreOneVertex) {
  // The quad as two triangles with their own copies of the diagonal's vertices: the same
  // values, so the same vertex to MikkTSpace, so the same tangent as the shared version.
  Mesh shared;
  addQuad(shared, 0.0f, 0.0f, 1.0f);
  shared.normals = {glm::normalize(glm::vec3(0.3f, 0, 1)), glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0, 0.4f, 1)),
                    glm::normalize(glm::vec3(-0.2f, 0.1f, 1))};
  Mesh split = shared;
  split.positions.push_back(shared.positions[0]);
  split.positions.push_back(shared.positions[2]);
  split.normals.push_back(shared.normals[0]);
  split.normals.push_back(shared.normals[2]);
  split.texcoords.push_back(shared.texcoords[0]);
  split.texcoords.push_back(shared.texcoords[2]);
  split.indices = {0, 1, 2, 4, 5, 3};
  generateTangents(shared);
  generateTangents(split);
  for (std::size_t v = 0; v < 4; ++v) expectNear(glm::vec3(split.tangents[v]), glm::vec3(shared.tangents[v]));
  expectNear(glm::vec3(split.tangents[4]), glm::vec3(shared.tangents[0]));
  expectNear(glm::vec3(split.tangents[5]), glm::vec3(shared.tangents[2]));
}

}  // namespace
}  // namespace iblkit
