#pragma once
// The environment stages taken from another bake folder instead of computed again (iblkit-bake
// --environment-from, the report's per-map environment stage, docs/baker.md "One map under several
// scenes"). The env/ files (bake_layout.h: SH9, irradiance cube, specular chain, DFG table, the
// dominant lights and the residual's SH9, chain and cube) depend on the map's bytes, its layout,
// rotation and intensity and the environment options alone, not on the scene: six scenes under one
// map prefiltered it six times. The suns' bounce (_SUNBOUNCE) depends on the scene and is traced
// by the bake that takes the stages, from the lights it reads back.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bakefile/bake_record.h"
#include "core/environment_lights.h"

namespace iblkit {

// The bake.json parameters the environment stages depend on besides the map (iblkit-bake's
// --sh-window, --specular-samples, --specular-size, --lut-size, --sun-threshold, --max-suns,
// --median-cut-levels), and the map's own (makeBakeRecord: --env-format, the rotation, the
// intensity).
inline constexpr const char* kEnvironmentParameters[] = {
    "sh_window",        "specular_samples", "specular_size",
    "lut_size",         "sun_threshold",    "max_suns",
    "median_cut_levels", "env_format",      "environment_rotation_degrees",
    "environment_intensity"};

// A hash (content_hash.h, 16 hex digits) of the map file's bytes. iblkit-bake records it in
// bake.json as "environment_hash". Throws Error naming the file when it cannot be read.
std::string environmentContentHash(const std::filesystem::path& map);

// The environment stages of another bake, for a bake whose map hashes to `environmentHash` and
// whose parameters (bake.json's, makeBakeRecord's) are `parameters`.
struct ReusedEnvironment {
  std::filesystem::path folder;  // the bake folder they come from
  EnvironmentLights lights;      // its env/lights.json, for the suns' bounce
  // Its env/ files (bake_layout.h names), each to be copied as it is.
  std::vector<const char*> files;
  nlohmann::json record;  // its bake.json's "environment" section
};

// Reads them from `bake`. Throws Error naming the file when `bake` is no bake folder (bake.json of
// kBakeVersion), when it has no environment stages, when a parameter above differs ("bake.json:
// environment baked with specular_samples 256, not 1024 (--environment-from needs the same map and
// environment options)"), when its environment_hash is not environmentHash (another map, or the
// map changed since), or when one of its env/ files is missing or its lights are invalid.
ReusedEnvironment reuseEnvironment(const std::filesystem::path& bake, const nlohmann::json& parameters,
                                   const std::string& environmentHash);

// Copies the env/ files of `reused` into the bake folder `folder` (creating env/), byte for byte.
// Throws Error naming the file that cannot be copied.
void copyReusedEnvironment(const ReusedEnvironment& reused, const std::filesystem::path& folder);

}  // namespace iblkit
