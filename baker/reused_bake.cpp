#include "baker/reused_bake.h"

#include <system_error>

#include "bakefile/bake_layout.h"
#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

json readBakeToReuse(const fs::path& bake, BakeInputs& inputs) {
  std::error_code error;
  if (!fs::is_directory(bake, error)) fail(bake, "no such bake folder");
  const fs::path recordFile = requireBakeFile(bake / kBakeRecordFile);
  json record = readBakeDocument(recordFile);  // read once: the inputs and parameters of one version of it
  inputs = bakeInputsOf(recordFile, record);    // the version and the inputs
  if (!record.contains("parameters") || !record["parameters"].is_object())
    fail(recordFile, "no parameters");
  return record;
}

void requireSameParameters(const fs::path& bake, const json& record, const json& parameters,
                           std::span<const char* const> names, const std::string& part, const std::string& option,
                           const std::string& what) {
  for (const char* name : names) {
    if (!record["parameters"].contains(name))
      fail(bake / kBakeRecordFile, "no parameter " + std::string(name) + " (a bake from before it was recorded?); " +
                                       option + " needs " + what);
    const json& theirs = record["parameters"][name];
    const json& ours = parameters.at(name);
    if (theirs != ours)
      fail(bake / kBakeRecordFile, part + " baked with " + name + " " + theirs.dump() + ", not " + ours.dump() + " (" +
                                       option + " needs " + what + ")");
  }
}

}  // namespace iblkit
