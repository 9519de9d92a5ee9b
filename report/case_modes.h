#pragma once
// Which engine modes a case scores: the one rule of the report (docs/report.md, "Only the modes
// that apply"), derived from the scene's materials.
//  - The diffuse-only modes (sh, irradiance, irradiance-ao-bent, sh-ao, sh-ao-bent, prt: albedo / pi
//    times some irradiance, engine/gl/shading_mode.h) approximate a diffuse lobe. A scene whose
//    every material is metallic (metallic 1, no metallicRoughnessTexture) has none: its diffuse
//    frames are black against a reflecting reference (the lone mirror sphere: FLIP 0.80, "sh beyond
//    SH9" 170%), which measures nothing. They are not scored there.
//  - `mirror` (the map along reflect(-v, n)) approximates a specular lobe. A scene whose every
//    material is pure Lambert (metallic 0 and specular 0, or a black specular colour) has none.
//  - The glTF occlusion modes (full-gltf-ao, the asset's occlusionTexture as the AO term;
//    full-both-ao, that times our baked per-vertex AO) read the material's occlusionTexture, and a
//    material without one has glTF occlusion 1: full-gltf-ao would then be unshadowed `full` and
//    full-both-ao exactly `full`, so they are scored only where some material has one.
// Every other mode (full, lights, lights-shadowed, unlit) shades both lobes and always applies.
// A textured factor (a metallicRoughnessTexture) counts as both lobes: the texture may hold any value.

#include <string>
#include <vector>

#include "core/scene.h"

namespace iblkit {

// The modes that read Material::occlusionTexture (the spellings of kShadingModeNames).
inline constexpr const char* kGltfOcclusionModes[] = {"full-gltf-ao", "full-both-ao"};
// The modes that shade only the diffuse lobe, and the one that shades only a perfect mirror.
inline constexpr const char* kDiffuseOnlyModes[] = {"sh", "irradiance", "irradiance-ao-bent", "sh-ao", "sh-ao-bent", "prt"};
inline constexpr const char* kSpecularOnlyModes[] = {"mirror"};

// What a scene's materials can use (of the materials its meshes use; a scene without meshes has
// every lobe, so that nothing is left out by accident).
struct SceneLobes {
  bool diffuse = true;           // some material with metallic < 1 (or a metallicRoughnessTexture)
  bool specular = true;          // some material with metallic > 0, or a dielectric specular > 0
  bool occlusionTexture = false; // some material with a glTF occlusionTexture
};
SceneLobes sceneLobes(const Scene& scene);

// True when some material of `scene` has an occlusion texture.
bool hasOcclusionTexture(const Scene& scene);

// Empty when `mode` applies to a scene with `lobes`, else why not (one phrase, for the page and
// report.json), e.g. "no diffuse lobe: every material is metallic".
std::string modeNotApplicable(const std::string& mode, const SceneLobes& lobes);

// `modes` in their order, less those that do not apply.
std::vector<std::string> caseModes(const std::vector<std::string>& modes, const SceneLobes& lobes);

}  // namespace iblkit
