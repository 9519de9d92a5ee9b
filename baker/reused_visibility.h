#pragma once
// Per-vertex visibility taken from another bake folder instead of traced again (iblkit-bake
// --visibility-from, the report's per-scene visibility stage, docs/baker.md "One scene under several
// maps"). The visibility attributes (_AO, _BENTNORMAL, _BENTLENGTH, _SHT0.._SHT2; bakefile/
// vertex_attributes.h) depend on the scene and the visibility options alone, not on the map: a
// scene baked under six maps traced them six times. The suns' bounce (_SUNBOUNCE) depends on the
// map's suns and is not taken.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/mesh.h"

namespace iblkit {

// The bake.json parameters that the visibility attributes depend on (iblkit-bake's --ao-rays,
// --ao-distance, --ao-falloff, --ao-area, --bounces, --seed).
inline constexpr const char* kVisibilityParameters[] = {"ao_rays", "ao_distance", "ao_falloff",
                                                        "ao_area", "bounces",     "seed"};

// Copies the visibility attributes of `bake`/scene.glb onto `meshes`, the meshes of the scene being
// baked, replacing any present. `parameters` holds this bake's parameters under the names above.
// Throws Error naming the file when `bake` is no bake folder (bake.json and scene.glb, of
// kBakeVersion), when a parameter above differs ("bake.json: visibility baked with ao_rays 64, not
// 256 (--visibility-from needs the same visibility options)"), when its meshes are not these (their
// number, a mesh's positions or triangles differ: "scene.glb: mesh 2 'bunny' is not the scene's"),
// or when an attribute is missing or of the wrong size.
void reuseVisibility(const std::filesystem::path& bake, const nlohmann::json& parameters, std::vector<Mesh>& meshes);

}  // namespace iblkit
