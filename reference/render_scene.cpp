#include "reference/render_scene.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/surface_material.h"
#include "core/tangent_frames.h"
#include "raytrace/alpha_filter.h"

namespace iblkit {

namespace {

// Whether a slot that shades (occlusion does not, in the tracer) reads a texture.
bool shadesWithTextures(const Material& m, unsigned slots) {
  return ((slots & kSlotBaseColor) && m.baseColorTexture.present()) ||
         ((slots & kSlotMetallicRoughness) && m.metallicRoughnessTexture.present()) ||
         ((slots & kSlotNormal) && m.normalTexture.present()) ||
         ((slots & kSlotEmissive) && m.emissiveTexture.present());
}

}  // namespace

RenderScene::RenderScene(Scene scene, unsigned textureSlots) : scene_(std::move(scene)), slots_(textureSlots) {
  std::vector<const Mesh*> geometryMeshes;
  for (unsigned i = 0; i < scene_.meshes.size(); ++i) {
    Mesh& mesh = scene_.meshes[i];
    if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene_.materials.size())
      fail(scene_.file, "mesh '" + mesh.name + "' uses material " + std::to_string(mesh.material) +
                            ", but the scene has " + std::to_string(scene_.materials.size()));
    if (mesh.triangleCount() == 0) continue;
    repairNormals(mesh);
    const Material& material = scene_.materials[static_cast<std::size_t>(mesh.material)];
    // The loaders generate tangents; a scene made in code may not have them.
    if (material.normalTexture.present() && mesh.tangents.size() != mesh.positions.size())
      generateTangents(mesh, material.normalTexture.texCoord);
    const unsigned geometry = rays_.addTriangleMesh(mesh.positions, mesh.indices);
    meshOfGeometry_.resize(geometry + 1);
    meshOfGeometry_[geometry] = i;
  }
  textures_ = scene_.textures.empty()
                  ? std::make_shared<SceneTextures>()
                  : std::make_shared<SceneTextures>(scene_.textures, scene_.images, scene_.materials);
  for (unsigned g = 0; g < meshOfGeometry_.size(); ++g) geometryMeshes.push_back(&scene_.meshes[meshOfGeometry_[g]]);
  auto filter = std::make_shared<AlphaFilter>(std::move(geometryMeshes), scene_.materials, textures_, slots_);
  bool anyTest = false;
  for (unsigned g = 0; g < filter->geometryCount(); ++g) anyTest = anyTest || filter->needs(g) != 0;
  if (anyTest) rays_.setAlphaFilter(std::move(filter));
  rays_.commit();
  // Vertex colours vary the material over a mesh like a texture does: such meshes are evaluated per
  // hit too, with their material prepared whether or not it reads a texture.
  colored_.resize(scene_.meshes.size());
  std::vector<bool> materialColored(scene_.materials.size(), false);
  for (unsigned i = 0; i < scene_.meshes.size(); ++i) {
    const Mesh& mesh = scene_.meshes[i];
    colored_[i] = !mesh.colors.empty() && mesh.colors.size() == mesh.positions.size();
    if (colored_[i]) materialColored[static_cast<std::size_t>(mesh.material)] = true;
  }
  lobes_.reserve(scene_.materials.size());
  for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
    const Material& material = scene_.materials[m];
    lobes_.push_back(brdfLobes(material));
    textured_.push_back(shadesWithTextures(material, slots_));
    // Occlusion is not applied: no need to read it.
    prepared_.push_back(textured_.back() || materialColored[m]
                            ? PreparedSurfaceMaterial(material, *textures_, slots_ & ~unsigned(kSlotOcclusion))
                            : PreparedSurfaceMaterial());
  }
  uvPerWorldLength_.resize(scene_.meshes.size());
  uvGradients_.resize(scene_.meshes.size());
  for (unsigned i = 0; i < scene_.meshes.size(); ++i) {
    const Mesh& mesh = scene_.meshes[i];
    if (mesh.triangleCount() == 0 || !textured_[static_cast<std::size_t>(mesh.material)]) continue;
    std::vector<glm::vec2>& lengths = uvPerWorldLength_[i];
    lengths.resize(mesh.triangleCount());
    for (std::size_t t = 0; t < lengths.size(); ++t)
      lengths[t] = glm::vec2(std::sqrt(uvPerWorldArea(mesh, t, 0)), std::sqrt(uvPerWorldArea(mesh, t, 1)));
    for (int set = 0; set < 2; ++set) {
      if ((set == 0 ? mesh.texcoords : mesh.texcoords1).size() != mesh.positions.size()) continue;
      std::vector<UvGradient>& gradients = uvGradients_[i][set];
      gradients.resize(mesh.triangleCount());
      for (std::size_t t = 0; t < gradients.size(); ++t) gradients[t] = uvGradient(mesh, t, set);
    }
  }
}

SurfacePoint RenderScene::surfacePoint(const Hit& hit, const glm::vec3& wo, const RayCone& cone) const {
  const Mesh& mesh = scene_.meshes[meshOfGeometry_[hit.geomId]];
  const std::uint32_t* corner = &mesh.indices[3 * static_cast<std::size_t>(hit.primId)];
  const glm::vec3 interpolated = interpolateAtHit(mesh.normals, corner, hit.barycentrics);

  SurfacePoint point;
  const RayScene::SurfacePosition position = rays_.surfacePosition(hit);
  point.position = position.point;
  point.positionError = position.error;
  point.geometricNormal =
      glm::dot(hit.geometricNormal, wo) < 0.0f ? -hit.geometricNormal : hit.geometricNormal;
  const float length = glm::length(interpolated);
  glm::vec3 shading = length > 0.0f ? interpolated / length : point.geometricNormal;
  const bool backSide = glm::dot(shading, point.geometricNormal) < 0.0f;
  if (backSide) shading = -shading;
  const auto materialIndex = static_cast<std::size_t>(mesh.material);
  const Material& material = scene_.materials[materialIndex];
  point.material = &material;
  point.isGround = mesh.isGround;

  const unsigned meshIndex = meshOfGeometry_[hit.geomId];
  if (!textured_[materialIndex] && !colored_[meshIndex]) {
    point.baseColor = material.baseColor;
    point.emissive = material.emissive;
    point.lobes = lobes_[materialIndex];
  } else {
    SurfaceInputs inputs;
    if (mesh.texcoords.size() == mesh.positions.size()) inputs.texcoords[0] = interpolateAtHit(mesh.texcoords, corner, hit.barycentrics);
    if (mesh.texcoords1.size() == mesh.positions.size())
      inputs.texcoords[1] = interpolateAtHit(mesh.texcoords1, corner, hit.barycentrics);
    inputs.normal = shading;
    if (mesh.tangents.size() == mesh.positions.size()) {
      const glm::vec4 t = interpolateAtHit(mesh.tangents, corner, hit.barycentrics);
      // Normalised but not re-orthogonalised: perturbNormal uses the interpolated frame as it
      // is, as MikkTSpace's notes and shaders/material.glsl do.
      glm::vec3 tangent(t);
      const float tangentLength = glm::length(tangent);
      if (tangentLength > 0.0f) {
        tangent /= tangentLength;
        // The back face of a double-sided surface: the tangent turns with the normal and w stays,
        // so the bitangent w cross(n, t) keeps its direction (SurfaceInputs).
        if (backSide) tangent = -tangent;
        inputs.tangent = glm::vec4(tangent, mesh.tangents[corner[0]].w < 0.0f ? -1.0f : 1.0f);
      }
    }
    if (colored_[meshIndex]) inputs.vertexColor = interpolateAtHit(mesh.colors, corner, hit.barycentrics);
    const float width = textured_[materialIndex] ? cone.widthAt(hit.t) : 0.0f;
    if (!textured_[materialIndex]) {
      // No texture to filter: no footprint.
    } else if (cone.pixel.present()) {
      const auto& gradients = uvGradients_[meshIndex];
      for (int set = 0; set < 2; ++set)
        if (!gradients[set].empty())
          inputs.footprintUv[set] = textureFootprintFromDifferentials(cone.pixel, -wo, hit.t, hit.geometricNormal,
                                                                      gradients[set][hit.primId]);
    } else if (width > 0.0f) {
      const float cosine = glm::dot(wo, point.geometricNormal);
      const glm::vec2 lengths = uvPerWorldLength_[meshIndex][hit.primId];
      for (int set = 0; set < 2; ++set)
        inputs.footprintUv[set] = textureFootprintFromLength(width, lengths[set], cosine);
    }
    const SurfaceMaterial surface = prepared_[materialIndex].evaluate(inputs);
    point.baseColor = surface.baseColor;
    point.emissive = surface.emissive;
    point.lobes = brdfLobes(surface);
    shading = surface.normal;
  }
  point.shadingNormal = shadingNormalFacingViewer(shading, wo, point.geometricNormal);
  return point;
}

}  // namespace iblkit
