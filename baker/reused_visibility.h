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
#include "core/scene.h"
#include <string>

namespace iblkit {

// The bake.json parameters that the visibility attributes depend on (iblkit-bake's --ao-rays,
// --ao-distance, --ao-falloff, --ao-area, --bounces, --seed).
inline constexpr const char* kVisibilityParameters[] = {"ao_rays", "ao_distance", "ao_falloff",
                                                        "ao_area", "bounces",     "seed"};

// A hash (content_hash.h, 16 hex digits) of the bytes of the files the scene was loaded from: the
// scene file, its glTF models and its texture images' own files, each once (a procedural shape's
// model entry, which names no file, by its name). Its materials (the
// albedo the bounces reflect with, the alpha masks the rays pass) and geometry come from these, so
// two bakes with the same hash and the same visibility parameters trace the same visibility.
// iblkit-bake records it in bake.json as "scene_hash". Throws Error naming a file it cannot read.
std::string sceneContentHash(const Scene& scene);

// Copies the visibility attributes of `bake`/scene.glb onto `scene`'s meshes (the scene being
// baked), replacing any present. `parameters` holds this bake's parameters under the names above.
// Throws Error naming the file when `bake` is no bake folder (bake.json and scene.glb, of
// kBakeVersion), when a parameter above differs ("bake.json: visibility baked with ao_rays 64, not
// 256 (--visibility-from needs the same visibility options)"), when its scene_hash is not
// sceneHash (other scene files, or a file changed since), when its meshes are not
// these (their number, a mesh's positions, triangles or ground flag differ: "scene.glb: mesh 2
// 'bunny' is not the scene's"), or when an attribute is missing or of the wrong size.
// `sceneHash` is sceneContentHash(scene), which the caller records too (computed once: it reads
// every scene file).
void reuseVisibility(const std::filesystem::path& bake, const nlohmann::json& parameters, const std::string& sceneHash,
                     Scene& scene);

}  // namespace iblkit
