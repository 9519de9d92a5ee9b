#pragma once
// bake.json of a bake folder (bake_layout.h): what was baked (the scene and the environment map
// with its layout, rotation and intensity) and how (the baker's parameters, timings and counts).
// Readers need only the inputs; the rest is for people and the report.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace iblkit {

// The most interreflection bounces a bake's SH transfer may hold (iblkit-bake --bounces, the
// report's --bake-bounces, and what bake.json's parameters.bounces may say).
inline constexpr int kMaxTransferBounces = 16;

// What a bake was made from.
struct BakeInputs {
  std::filesystem::path scene;
  // Empty: the bake has no environment stages. Written absolute, so the bake loads from any
  // working directory; a relative one (a hand-written bake.json) is relative to the bake folder.
  std::filesystem::path environment;
  std::string environmentFormat = "latlong";  // core/environment_map_file.h: parseProbeFormat
  float environmentRotationDegrees = 0.0f;    // about +Y, core/environment_map.h
  float environmentIntensity = 1.0f;
  // Interreflection bounces in the SH transfer (parameters.bounces, iblkit-bake --bounces; 0 where
  // the record has none: bakes from before it was read). The engine's diffuse multi-bounce fit
  // stands in for interreflection only where the transfer holds none (docs/engine.md, `full`).
  int transferBounces = 0;
};

// The bake.json document for `inputs`: "version" (kBakeVersion), "inputs" {scene, environment}
// and "parameters" holding `parameters` plus environment_rotation_degrees, environment_intensity
// and env_format. The baker adds its own sections ("timings", "counts", ...) before writing it.
nlohmann::json makeBakeRecord(const BakeInputs& inputs, nlohmann::json parameters);

// Writes `record` to `file` (temporary name, then rename). Throws Error("<file>: ...").
void writeBakeRecord(const std::filesystem::path& file, const nlohmann::json& record);

// Reads the inputs back from `file` (a bake folder's bake.json). Throws Error("<file>: ...") for a
// missing or invalid file, a "version" other than kBakeVersion, missing input records, or a
// parameters.bounces that is not an integer in 0..kMaxTransferBounces.
BakeInputs readBakeRecord(const std::filesystem::path& file);

// readBakeRecord in two steps, for a caller that keeps the document: `file` parsed (Error
// "<file>: ..." when it is missing or not JSON), then the inputs of that document (the checks
// above, errors naming `file`).
nlohmann::json readBakeDocument(const std::filesystem::path& file);
BakeInputs bakeInputsOf(const std::filesystem::path& file, const nlohmann::json& record);

}  // namespace iblkit
