#include "report/case_modes.h"

#include <algorithm>
#include <iterator>

namespace iblkit {

bool hasOcclusionTexture(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& material) { return material.occlusionTexture.present(); });
}

std::vector<std::string> caseModes(const std::vector<std::string>& modes, bool occlusionTexture) {
  std::vector<std::string> result;
  for (const std::string& mode : modes) {
    const bool gltfOcclusion = std::find(std::begin(kGltfOcclusionModes), std::end(kGltfOcclusionModes), mode) !=
                               std::end(kGltfOcclusionModes);
    if (occlusionTexture || !gltfOcclusion) result.push_back(mode);
  }
  return result;
}

}  // namespace iblkit
