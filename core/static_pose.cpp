#include "core/static_pose.h"

#include <algorithm>

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

}  // namespace iblkit
