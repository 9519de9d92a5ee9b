#include "report/stage_plan.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "core/input_file.h"
#include "report/stage_cache.h"
#include "report/stage_run.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

void writeStagePlan(const fs::path& file, const fs::path& cacheRoot, const std::vector<PendingStage>& stages) {
  json plan{{"cache", fs::absolute(cacheRoot).string()}, {"directory", fs::current_path().string()},
            {"stages", json::array()}};
  for (const PendingStage& stage : stages) {
    json inputs = json::array();
    for (const fs::path& input : stage.command.inputFiles) inputs.push_back(input.string());
    plan["stages"].push_back({{"name", stage.name},
                              {"key", stage.key},
                              {"case", stage.caseName},
                              {"program", stage.command.program.string()},
                              {"arguments", stage.command.arguments},
                              {"inputFiles", inputs}});
  }
  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary);
    stream << plan.dump(1) << '\n';
    if (!stream.flush()) fail(file, "cannot write the stage plan");
  });
}

StagePlan readStagePlan(const fs::path& file) {
  // A regular file of bounded size and nesting (core/input_file.h): not a FIFO or a device.
  const json plan = json::parse(readJsonText(file), nullptr, false);
  StagePlan result;
  try {
    if (plan.is_discarded()) fail(file, "the stage plan is not JSON");
    result.cacheRoot = plan.at("cache").get<std::string>();
    result.workingFolder = plan.at("directory").get<std::string>();
    for (const json& stage : plan.at("stages")) {
      PendingStage pending;
      pending.name = stage.at("name").get<std::string>();
      pending.key = stage.at("key").get<std::string>();
      pending.caseName = stage.at("case").get<std::string>();
      pending.command.program = stage.at("program").get<std::string>();
      pending.command.arguments = stage.at("arguments").get<std::vector<std::string>>();
      for (const json& input : stage.at("inputFiles")) pending.command.inputFiles.push_back(input.get<std::string>());
      result.stages.push_back(std::move(pending));
    }
  } catch (const json::exception& e) {
    fail(file, std::string("malformed stage plan: ") + e.what());
  }
  return result;
}

void runStageTask(const fs::path& planFile, int index) {
  const StagePlan plan = readStagePlan(fs::absolute(planFile));
  if (index < 0 || index >= int(plan.stages.size()))
    fail(planFile, "task " + std::to_string(index) + " is not in the plan (it has " +
                       std::to_string(plan.stages.size()) + " stages)");
  if (::chdir(plan.workingFolder.c_str()) != 0)
    fail(plan.workingFolder, std::string("cannot change to the report's folder: ") + std::strerror(errno));
  const PendingStage& stage = plan.stages[std::size_t(index)];
  if (stageKey(stage.command) != stage.key)
    fail(planFile, "stage " + stage.name + ": its program or an input file changed since it was submitted");
  const StageCache cache(plan.cacheRoot);
  runStage(cache, stage.name, stage.command);
}

}  // namespace iblkit
