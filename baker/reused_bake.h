#pragma once
// What --visibility-from and --environment-from (reused_visibility.h, reused_environment.h) check
// first in the bake folder they take a part from: that it is a bake, and that it was baked with the
// same parameters as the bake that takes the part.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "bakefile/bake_record.h"

namespace iblkit {

// `bake`'s bake.json, its inputs into `inputs`. Throws Error naming the file when `bake` is no
// folder ("no such bake folder"), when bake.json is missing, invalid or of another version
// (readBakeRecord), or when it has no "parameters" object.
nlohmann::json readBakeToReuse(const std::filesystem::path& bake, BakeInputs& inputs);

// Throws Error("<bake>/bake.json: <part> baked with <name> <theirs>, not <ours> (<option> needs
// <what>)") for the first of `names` whose value in `record`'s parameters differs from the one in
// `parameters` (the bake being made: makeBakeRecord's parameters, holding every name), and
// Error("<bake>/bake.json: no parameter <name> (a bake from before it was recorded?); <option>
// needs <what>") for one that `record` lacks.
void requireSameParameters(const std::filesystem::path& bake, const nlohmann::json& record,
                           const nlohmann::json& parameters, std::span<const char* const> names, const std::string& part,
                           const std::string& option, const std::string& what);

}  // namespace iblkit
