#include "reference/render_scene.h"

#include <string>

#include "core/error.h"

namespace iblkit {

RenderScene::RenderScene(Scene scene) : scene_(std::move(scene)) {
  for (unsigned i = 0; i < scene_.meshes.size(); ++i) {
    Mesh& mesh = scene_.meshes[i];
    if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene_.materials.size())
      fail(scene_.file, "mesh '" + mesh.name + "' uses material " + std::to_string(mesh.material) +
                            ", but the scene has " + std::to_string(scene_.materials.size()));
    if (mesh.triangleCount() == 0) continue;
    repairNormals(mesh);
    const unsigned geometry = rays_.addTriangleMesh(mesh.positions, mesh.indices);
    meshOfGeometry_.resize(geometry + 1);
    meshOfGeometry_[geometry] = i;
  }
  rays_.commit();
  lobes_.reserve(scene_.materials.size());
  for (const Material& material : scene_.materials) lobes_.push_back(brdfLobes(material));
}

SurfacePoint RenderScene::surfacePoint(const Hit& hit, const glm::vec3& wo) const {
  const Mesh& mesh = scene_.meshes[meshOfGeometry_[hit.geomId]];
  const std::size_t corner = 3 * static_cast<std::size_t>(hit.primId);
  const float u = hit.barycentrics.x, v = hit.barycentrics.y;
  const glm::vec3 interpolated = (1.0f - u - v) * mesh.normals[mesh.indices[corner]] +
                                 u * mesh.normals[mesh.indices[corner + 1]] +
                                 v * mesh.normals[mesh.indices[corner + 2]];

  SurfacePoint point;
  point.position = rays_.surfacePoint(hit);
  point.geometricNormal =
      glm::dot(hit.geometricNormal, wo) < 0.0f ? -hit.geometricNormal : hit.geometricNormal;
  const float length = glm::length(interpolated);
  glm::vec3 shading = length > 0.0f ? interpolated / length : point.geometricNormal;
  if (glm::dot(shading, point.geometricNormal) < 0.0f) shading = -shading;
  point.shadingNormal = glm::dot(shading, wo) > 0.0f ? shading : point.geometricNormal;
  point.material = &scene_.materials[static_cast<std::size_t>(mesh.material)];
  point.lobes = &lobes_[static_cast<std::size_t>(mesh.material)];
  point.isGround = mesh.isGround;
  return point;
}

}  // namespace iblkit
