#pragma once
// Which engine modes a case scores. The glTF occlusion modes (engine/gl/shading_mode.h:
// full-gltf-ao, the asset's occlusionTexture as the AO term; full-both-ao, that times our baked
// per-vertex AO) read the material's occlusionTexture, and a material without one has glTF
// occlusion 1: full-gltf-ao would then be unshadowed `full` and full-both-ao exactly `full`, so
// they are scored only on scenes where some material has an occlusion texture (docs/report.md).

#include <string>
#include <vector>

#include "core/scene.h"

namespace iblkit {

// The modes that read Material::occlusionTexture (the spellings of kShadingModeNames).
inline constexpr const char* kGltfOcclusionModes[] = {"full-gltf-ao", "full-both-ao"};

// True when some material of `scene` has an occlusion texture.
bool hasOcclusionTexture(const Scene& scene);

// `modes` in their order, less the glTF occlusion modes when `occlusionTexture` is false.
std::vector<std::string> caseModes(const std::vector<std::string>& modes, bool occlusionTexture);

}  // namespace iblkit
