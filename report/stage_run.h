#pragma once
// Runs a stage's command through the stage cache (stage_cache.h) under its key (stage_command.h).

#include <filesystem>
#include <string>

#include "report/stage_cache.h"
#include "report/stage_command.h"

namespace iblkit {

// A finished stage: its folder, how long it took when it ran and its command line.
struct StageRun {
  std::filesystem::path folder;
  double seconds = 0.0;
  std::string command;
  // Not run: the cache collects missing stages (StageCache::collectInto), and this one is missing.
  // The folder is where it will be; nothing is in it yet.
  bool pending = false;
};

// The stage `name` of `command`: when not cached, runs it (its output into the stage's folder, its
// log into log.txt there) and records its wall time and command line in stage.json, so that a
// cached stage reports the time and command of the run that made it. Throws Error when the program
// fails or the record is unreadable. When the cache collects missing stages, a missing stage is
// added to them and comes back pending instead, with the folders of the missing stages it reads.
StageRun runStage(const StageCache& cache, const std::string& name, const StageCommand& command);

}  // namespace iblkit
