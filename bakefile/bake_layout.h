#pragma once
// The bake folder, the file format iblkit-bake writes and the engine, the viewer and the report
// read (docs/baker.md). Every path below is relative to the folder; this header is the one place
// that spells them, and the version of the layout they make up.
//
//   bake.json           inputs, parameters, timings and counts (bake_record.h)
//   scene.glb           the flattened scene with the baked vertex attributes (scene_glb.h,
//                       vertex_attributes.h)
//   env/sh9.json        SH9 radiance of the environment (sh9_json.h)
//   env/irradiance.exr  brute-force irradiance cube (irradiance_exr.h)
//   env/specular.exr    GGX-prefiltered specular cube chain (specular_exr.h)
//   env/brdf_lut.exr    split-sum DFG table (brdf_lut_exr.h)
//   env/lights.json     extracted suns and median-cut lights (environment_lights_json.h)
//   env/residual_sh9.json, env/residual_specular.exr
//                       SH9 and specular chain of the map without its suns
// The env/ files exist only when the bake had an environment map.

#include <filesystem>

namespace iblkit {

// The "version" of bake.json this code writes and reads; a change to the layout or to the meaning
// of a file bumps it.
inline constexpr const char* kBakeVersion = "iblkit-bake 1";

inline constexpr const char* kBakeRecordFile = "bake.json";
inline constexpr const char* kBakeSceneFile = "scene.glb";
inline constexpr const char* kBakeSh9File = "env/sh9.json";
inline constexpr const char* kBakeIrradianceFile = "env/irradiance.exr";
inline constexpr const char* kBakeSpecularFile = "env/specular.exr";
inline constexpr const char* kBakeBrdfLutFile = "env/brdf_lut.exr";
inline constexpr const char* kBakeLightsFile = "env/lights.json";
inline constexpr const char* kBakeResidualSh9File = "env/residual_sh9.json";
inline constexpr const char* kBakeResidualSpecularFile = "env/residual_specular.exr";
inline constexpr const char* kBakeResidualIrradianceFile = "env/residual_irradiance.exr";
// Every env/ file of a bake with a map, in the order bake.json's "outputs" lists them. The two
// irradiance cubes are missing from bakes made before them (readEnvironmentStages).
inline constexpr const char* kBakeEnvironmentFiles[] = {
    kBakeSh9File,    kBakeIrradianceFile,  kBakeSpecularFile,         kBakeBrdfLutFile,
    kBakeLightsFile, kBakeResidualSh9File, kBakeResidualSpecularFile, kBakeResidualIrradianceFile};

// `file`, a file of a bake folder that a reader needs. Throws Error("<file>: missing (incomplete
// bake folder?)") unless it is a regular file.
std::filesystem::path requireBakeFile(const std::filesystem::path& file);

}  // namespace iblkit
