#include "core/mesh.h"

#include <cmath>
#include <utility>

namespace iblkit {

void Bounds::extend(const glm::vec3& point) {
  min = glm::min(min, point);
  max = glm::max(max, point);
}

void Bounds::extend(const Bounds& other) {
  if (other.empty()) return;
  extend(other.min);
  extend(other.max);
}

glm::vec3 Bounds::center() const { return empty() ? glm::vec3(0.0f) : 0.5f * (min + max); }

float Bounds::radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }

std::array<glm::vec3, 8> Bounds::corners() const {
  std::array<glm::vec3, 8> result;
  for (int i = 0; i < 8; ++i)
    result[i] = glm::vec3((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
  return result;
}

Bounds Mesh::bounds() const {
  Bounds b;
  for (const glm::vec3& p : positions) b.extend(p);
  return b;
}

bool Mesh::hasVertexAlpha() const {
  for (const glm::vec4& c : colors)
    if (c.a < 1.0f) return true;
  return false;
}

std::vector<glm::vec3> angleWeightedNormals(std::span<const glm::vec3> positions,
                                            std::span<const std::uint32_t> indices) {
  std::vector<glm::vec3> sums(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t corner[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const glm::vec3 faceNormal =
        glm::cross(positions[corner[1]] - positions[corner[0]], positions[corner[2]] - positions[corner[0]]);
    const float twiceArea = glm::length(faceNormal);
    if (!(twiceArea > 0.0f) || !std::isfinite(twiceArea)) continue;
    const glm::vec3 unitNormal = faceNormal / twiceArea;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 toNext = positions[corner[(k + 1) % 3]] - positions[corner[k]];
      const glm::vec3 toPrevious = positions[corner[(k + 2) % 3]] - positions[corner[k]];
      // The interior angle via atan2(|u x v|, u . v): accurate for small and obtuse angles alike.
      const float angle =
          std::atan2(glm::length(glm::cross(toNext, toPrevious)), glm::dot(toNext, toPrevious));
      sums[corner[k]] += angle * unitNormal;
    }
  }
  for (glm::vec3& n : sums) {
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return sums;
}

namespace {
bool isUsableNormal(const glm::vec3& n) {
  const float length = glm::length(n);
  return std::isfinite(length) && length > 0.0f;
}
}  // namespace

std::size_t repairNormals(Mesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) {
    mesh.normals = angleWeightedNormals(mesh.positions, mesh.indices);
    return mesh.normals.size();
  }
  std::size_t bad = 0;
  for (const glm::vec3& n : mesh.normals) bad += isUsableNormal(n) ? 0 : 1;
  if (bad == 0) return 0;
  const std::vector<glm::vec3> generated = angleWeightedNormals(mesh.positions, mesh.indices);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i)
    if (!isUsableNormal(mesh.normals[i])) mesh.normals[i] = generated[i];
  return bad;
}

std::size_t removeZeroAreaTriangles(Mesh& mesh) {
  std::size_t kept = 0;
  const std::size_t total = mesh.triangleCount();
  for (std::size_t t = 0; t < total; ++t) {
    const std::uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
    const glm::vec3 cross =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    if (cross == glm::vec3(0.0f)) continue;
    mesh.indices[3 * kept] = a;
    mesh.indices[3 * kept + 1] = b;
    mesh.indices[3 * kept + 2] = c;
    ++kept;
  }
  mesh.indices.resize(3 * kept);
  return total - kept;
}

long long firstVertexOutOfRange(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(mesh.positions[i][c]) <= kMaxSceneCoordinate)) return static_cast<long long>(i);
  return -1;
}

namespace {

// An affine transform of one vertex's position, normal and tangent (transformMesh's rules).
struct VertexTransform {
  glm::mat4 matrix;
  glm::mat3 linear;
  glm::mat3 normalMatrix;  // the cofactor matrix det(M) M^-T times the sign of det(M)
  bool mirrors;

  explicit VertexTransform(const glm::mat4& m) : matrix(m), linear(m) {
    const float determinant = glm::determinant(linear);
    mirrors = determinant < 0.0f;
    // Columns c1 x c2, c2 x c0, c0 x c1: the cofactor matrix, det(M) M^-T.
    const glm::mat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                             glm::cross(linear[0], linear[1]));
    normalMatrix = mirrors ? -cofactor : cofactor;
  }

  void apply(Mesh& mesh, std::size_t i) const {
    mesh.positions[i] = glm::vec3(matrix * glm::vec4(mesh.positions[i], 1.0f));
    if (i < mesh.normals.size()) {
      glm::vec3 n = normalMatrix * mesh.normals[i];
      const float length = glm::length(n);
      mesh.normals[i] = length > 0.0f ? n / length : n;
    }
    // Tangents are directions in the surface (dp/du), so they move by M itself, not the normal
    // matrix; re-orthogonalised to the new normal (a non-uniform scale shears them off its plane).
    // A mirror reverses cross(n, t), so w changes sign with det(M) to keep the bitangent
    // w cross(n, t) pointing along the same uv direction.
    if (i < mesh.tangents.size()) {
      glm::vec3 t = linear * glm::vec3(mesh.tangents[i]);
      if (i < mesh.normals.size()) t -= mesh.normals[i] * glm::dot(mesh.normals[i], t);
      const float length = glm::length(t);
      if (length > 0.0f) t /= length;
      mesh.tangents[i] = glm::vec4(t, mesh.tangents[i].w * (mirrors ? -1.0f : 1.0f));
    }
  }
};

void flipWinding(Mesh& mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

}  // namespace

void transformMesh(Mesh& mesh, const glm::mat4& transform) {
  const VertexTransform vertex(transform);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) vertex.apply(mesh, i);
  if (vertex.mirrors) flipWinding(mesh);
}

void transformMeshPerVertex(Mesh& mesh, std::span<const glm::mat4> matrices) {
  std::size_t mirrored = 0;
  for (std::size_t i = 0; i < mesh.positions.size() && i < matrices.size(); ++i) {
    const VertexTransform vertex(matrices[i]);
    vertex.apply(mesh, i);
    mirrored += vertex.mirrors;
  }
  if (2 * mirrored > mesh.positions.size()) flipWinding(mesh);
}

}  // namespace iblkit
