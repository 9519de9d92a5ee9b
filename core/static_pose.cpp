#include "core/static_pose.h"

#include <algorithm>
#include <utility>

namespace iblkit {

void applyMorphTargets(Mesh& mesh, std::span<const MorphTarget> targets, std::span<const float> weights) {
  const std::size_t count = std::min(targets.size(), weights.size());
  for (std::size_t t = 0; t < count; ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = targets[t];
    if (target.positions.size() == mesh.positions.size())
      for (std::size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] += w * target.positions[i];
    if (target.normals.size() == mesh.normals.size())
      for (std::size_t i = 0; i < mesh.normals.size(); ++i) mesh.normals[i] += w * target.normals[i];
    if (target.tangents.size() == mesh.tangents.size())
      for (std::size_t i = 0; i < mesh.tangents.size(); ++i)
        mesh.tangents[i] += glm::vec4(w * target.tangents[i], 0.0f);
  }
}

std::vector<glm::mat4> skinningMatrices(std::span<const VertexInfluences> influences,
                                        std::span<const glm::mat4> jointMatrices) {
  std::vector<glm::mat4> matrices(influences.size(), glm::mat4(1.0f));
  for (std::size_t v = 0; v < influences.size(); ++v) {
    const VertexInfluences& in = influences[v];
    float sum = 0.0f;
    for (const float w : in.weights) sum += w;
    if (!(sum > 0.0f)) continue;
    glm::mat4 m(0.0f);
    for (std::size_t k = 0; k < in.weights.size(); ++k)
      if (in.weights[k] != 0.0f) m += (in.weights[k] / sum) * jointMatrices[in.joints[k]];
    matrices[v] = m;
  }
  return matrices;
}

void transformMeshPerVertex(Mesh& mesh, std::span<const glm::mat4> matrices) {
  std::size_t mirrored = 0;
  for (std::size_t i = 0; i < mesh.positions.size() && i < matrices.size(); ++i) {
    const glm::mat4& m = matrices[i];
    mesh.positions[i] = glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f));
    const glm::mat3 linear(m);
    const float determinant = glm::determinant(linear);
    mirrored += determinant < 0.0f;
    // The cofactor matrix det(M) M^-T (columns c1 x c2, c2 x c0, c0 x c1), as transformMesh.
    const glm::mat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                             glm::cross(linear[0], linear[1]));
    if (i < mesh.normals.size()) {
      glm::vec3 n = (determinant < 0.0f ? -cofactor : cofactor) * mesh.normals[i];
      const float length = glm::length(n);
      mesh.normals[i] = length > 0.0f ? n / length : n;
    }
    if (i < mesh.tangents.size()) {
      glm::vec3 t = linear * glm::vec3(mesh.tangents[i]);
      if (i < mesh.normals.size()) t -= mesh.normals[i] * glm::dot(mesh.normals[i], t);
      const float length = glm::length(t);
      if (length > 0.0f) t /= length;
      mesh.tangents[i] = glm::vec4(t, mesh.tangents[i].w * (determinant < 0.0f ? -1.0f : 1.0f));
    }
  }
  if (2 * mirrored > mesh.positions.size())
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

}  // namespace iblkit
