#include "bakefile/bake_record.h"

#include <fstream>

#include "bakefile/bake_layout.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/input_file.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

json makeBakeRecord(const BakeInputs& inputs, json parameters) {
  parameters["env_format"] = inputs.environmentFormat;
  parameters["environment_rotation_degrees"] = inputs.environmentRotationDegrees;
  parameters["environment_intensity"] = inputs.environmentIntensity;
  return {{"version", kBakeVersion},
          {"inputs",
           {{"scene", inputs.scene.string()},
            {"environment", inputs.environment.empty() ? json(nullptr) : json(inputs.environment.string())}}},
          {"parameters", std::move(parameters)}};
}

void writeBakeRecord(const fs::path& file, const json& record) {
  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary);
    stream << record.dump(2) << '\n';
    if (!stream.flush()) fail(file, "cannot write file");
  });
}

json readBakeDocument(const fs::path& file) {
  const std::string text = readJsonText(requireBakeFile(file));
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    fail(file, std::string("not valid JSON: ") + e.what());
  }
}

BakeInputs readBakeRecord(const fs::path& file) { return bakeInputsOf(file, readBakeDocument(file)); }

BakeInputs bakeInputsOf(const fs::path& file, const json& record) {
  // Any JSON value may stand there: a string is the version, anything else is shown as JSON (a
  // number made json::value throw a type_error that named no file; found by fuzz/fuzz_bake_record).
  std::string version;
  if (record.is_object() && record.contains("version"))
    version = record["version"].is_string() ? record["version"].get<std::string>() : record["version"].dump();
  if (version != kBakeVersion)
    fail(file, "version '" + printableExcerpt(version) + "' is not supported (expected '" + kBakeVersion + "')");
  BakeInputs inputs;
  if (record.contains("parameters") && record["parameters"].is_object() && record["parameters"].contains("bounces")) {
    const json& bounces = record["parameters"]["bounces"];
    if (!bounces.is_number_integer() || bounces.get<long long>() < 0 || bounces.get<long long>() > kMaxTransferBounces)
      fail(file, "parameters.bounces: expected an integer in 0.." + std::to_string(kMaxTransferBounces) + ", got " +
                     printableExcerpt(bounces.dump()));
    inputs.transferBounces = int(bounces.get<long long>());
  }
  try {
    const json& recorded = record.at("inputs");
    inputs.scene = recorded.at("scene").get<std::string>();
    const json& environment = recorded.at("environment");
    if (environment.is_null()) return inputs;
    inputs.environment = environment.get<std::string>();
    if (inputs.environment.is_relative()) inputs.environment = file.parent_path() / inputs.environment;
    const json& parameters = record.at("parameters");
    inputs.environmentRotationDegrees = parameters.at("environment_rotation_degrees").get<float>();
    inputs.environmentIntensity = parameters.at("environment_intensity").get<float>();
    inputs.environmentFormat = parameters.value("env_format", std::string("latlong"));
  } catch (const json::exception& e) {
    fail(file, std::string("missing environment record: ") + e.what());
  }
  return inputs;
}

}  // namespace iblkit
