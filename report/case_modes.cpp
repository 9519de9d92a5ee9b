#include "report/case_modes.h"

#include <algorithm>
#include <iterator>

namespace iblkit {

namespace {

template <std::size_t N>
bool contains(const char* const (&list)[N], const std::string& mode) {
  return std::find(std::begin(list), std::end(list), mode) != std::end(list);
}

}  // namespace

SceneLobes sceneLobes(const Scene& scene) {
  std::vector<const Material*> used;
  for (const Mesh& mesh : scene.meshes)
    if (mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size())
      used.push_back(&scene.materials[std::size_t(mesh.material)]);
  if (used.empty())
    for (const Material& material : scene.materials) used.push_back(&material);
  SceneLobes lobes;
  lobes.occlusionTexture = hasOcclusionTexture(scene);
  if (used.empty()) return lobes;
  lobes.diffuse = lobes.specular = false;
  for (const Material* material : used) {
    const GltfRangeFactors factors = clampedFactors(*material);
    const bool textured = material->metallicRoughnessTexture.present();
    lobes.diffuse |= textured || factors.metallic < 1.0f;
    lobes.specular |= textured || factors.metallic > 0.0f ||
                      (factors.specular > 0.0f && std::max({factors.specularColor.r, factors.specularColor.g,
                                                            factors.specularColor.b}) > 0.0f);
  }
  return lobes;
}

bool hasOcclusionTexture(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& material) { return material.occlusionTexture.present(); });
}

std::string modeNotApplicable(const std::string& mode, const SceneLobes& lobes) {
  if (contains(kGltfOcclusionModes, mode) && !lobes.occlusionTexture)
    return "no material has an occlusion texture: it would repeat full";
  if (contains(kDiffuseOnlyModes, mode) && !lobes.diffuse) return "no diffuse lobe: every material is metallic";
  if (contains(kSpecularOnlyModes, mode) && !lobes.specular)
    return "no specular lobe: every material is pure Lambert";
  return {};
}

std::vector<std::string> caseModes(const std::vector<std::string>& modes, const SceneLobes& lobes) {
  std::vector<std::string> result;
  for (const std::string& mode : modes)
    if (modeNotApplicable(mode, lobes).empty()) result.push_back(mode);
  return result;
}

}  // namespace iblkit
