#include "engine/gl/render_space.h"

namespace iblkit {

RenderSpace RenderSpace::of(const Scene& scene) {
  Bounds bounds = scene.bounds;
  if (bounds.empty())
    for (const Mesh& mesh : scene.meshes) bounds.extend(mesh.bounds());
  // A float origin: the subtraction p - origin of a vertex near it is then exact.
  return {glm::dvec3(bounds.empty() ? glm::vec3(0.0f) : bounds.center())};
}

Mesh RenderSpace::shape(const Mesh& mesh) const {
  Mesh out;
  out.name = mesh.name;
  out.positions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) out.positions.push_back(fromWorld(p));
  out.indices = mesh.indices;
  out.isGround = mesh.isGround;
  return out;
}

}  // namespace iblkit
