#include "baker/reused_environment.h"

#include <string_view>
#include <system_error>

#include "bakefile/bake_layout.h"
#include "bakefile/environment_lights_json.h"
#include "baker/reused_bake.h"
#include "core/content_hash.h"
#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

std::string environmentContentHash(const fs::path& map) { return ContentHash().addFile(map).hex(); }

ReusedEnvironment reuseEnvironment(const fs::path& bake, const json& parameters, const std::string& environmentHash) {
  BakeInputs inputs;
  const json record = readBakeToReuse(bake, inputs);
  const fs::path recordFile = bake / kBakeRecordFile;
  if (inputs.environment.empty())
    fail(recordFile, "the bake has no environment stages (--environment-from needs a bake with a map)");
  requireSameParameters(bake, record, parameters, kEnvironmentParameters, "environment", "--environment-from",
                        "the same map and environment options");
  if (!record.contains("environment_hash") || record["environment_hash"] != environmentHash)
    fail(recordFile, "baked from another map than this bake's (its environment_hash differs: another file, or the "
                     "map changed since)");
  std::error_code error;
  ReusedEnvironment reused;
  reused.folder = bake;
  reused.record = record.contains("environment") ? record["environment"] : json();
  if (!reused.record.is_object()) fail(recordFile, "no environment section");
  // The files in the order iblkit-bake lists them; the two irradiance cubes only where they exist
  // (readEnvironmentStages: bakes from before them have none), every other one required.
  for (const char* file : kBakeEnvironmentFiles) {
    const std::string_view name = file;
    const bool optional = name == kBakeIrradianceFile || name == kBakeResidualIrradianceFile;
    if (optional && !fs::is_regular_file(bake / file, error)) continue;
    requireBakeFile(bake / file);
    reused.files.push_back(file);
  }
  reused.lights = readEnvironmentLightsJson(bake / kBakeLightsFile);
  return reused;
}

void copyReusedEnvironment(const ReusedEnvironment& reused, const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder / fs::path(kBakeSh9File).parent_path(), error);
  if (error) fail(folder / fs::path(kBakeSh9File).parent_path(), "cannot create folder: " + error.message());
  for (const char* file : reused.files) {
    fs::copy_file(reused.folder / file, folder / file, fs::copy_options::overwrite_existing, error);
    if (error) fail(reused.folder / file, "cannot copy into " + (folder / file).string() + ": " + error.message());
  }
}

}  // namespace iblkit
