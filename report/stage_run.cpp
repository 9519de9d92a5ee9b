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
    // A failed stage's temporary folder is removed: its log is kept beside the cache's stage folders
    // (NAME-KEY.failed.log), where the error points; a later run that succeeds removes it.
    const fs::path log = folder / "log.txt", kept = cache.folder(name, key).string() + ".failed.log";
    std::error_code error;
    try {
      runProgram(argv, log);
    } catch (const Error& e) {
      fs::copy_file(log, kept, fs::copy_options::overwrite_existing, error);
      if (error) throw;
      std::string message = e.what();
      if (const std::size_t at = message.rfind(log.string()); at != std::string::npos)
        message.replace(at, log.string().size(), kept.string());
      throw Error(message);
    }
    fs::remove(kept, error);
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
