#include "report/stage_run.h"

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "report/pending_stages.h"
#include "report/program_runner.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

StageRun runStage(const StageCache& cache, const std::string& name, const StageCommand& command) {
  StageRun run;
  const std::string key = stageKey(command);
  if (PendingStages* pending = cache.collecting()) {
    std::error_code error;
    if (!fs::is_directory(cache.folder(name, key), error)) {
      PendingStage stage{name, key, {}, command, {}};
      for (const std::string& folder : stageFoldersRead(command))
        if (!fs::is_directory(cache.root() / folder, error)) stage.needs.push_back(folder);
      pending->add(std::move(stage));
      run.folder = cache.folder(name, key);
      run.command = commandLine(stageArgv(command, cache.root(), run.folder));
      run.pending = true;
      return run;
    }
  }
  run.folder = cache.stage(name, key, [&](const fs::path& folder) {
    const std::vector<std::string> argv = stageArgv(command, cache.root(), folder);
    const auto start = std::chrono::steady_clock::now();
    runProgram(argv, folder / "log.txt");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Checked: a stage folder is renamed into the cache only with its whole record.
    std::ofstream record(folder / "stage.json");
    record << json{{"seconds", seconds}, {"command", commandLine(argv)}}.dump(2);
    if (!record.flush()) fail(folder / "stage.json", "cannot write the stage record");
  });
  std::ifstream stream(run.folder / "stage.json");
  const json record = json::parse(stream, nullptr, false);
  if (record.is_discarded() || !record.contains("seconds"))
    fail(run.folder / "stage.json", "unreadable stage record");
  run.seconds = record["seconds"].get<double>();
  run.command = record["command"].get<std::string>();
  return run;
}

}  // namespace iblkit
