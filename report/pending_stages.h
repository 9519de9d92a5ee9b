#pragma once
// The stages a report pass found missing from the cache when it is told to collect them rather
// than run them (StageCache::collectInto): what a scheduler (slurm_scheduler.h) then runs
// elsewhere. A pass that collects goes as far as the cache lets it: a case whose bake is missing
// still collects its engine frames (which read the bake, so they need it) and its first reference
// passes (which need nothing), and stops where it would have to read a missing stage's output.

#include <set>
#include <string>
#include <vector>

#include "report/stage_command.h"

namespace iblkit {

struct PendingStage {
  std::string name, key;  // the stage's folder in the cache is NAME-KEY (stage_cache.h)
  std::string caseName;   // the case that asked for it ("bunny under sky"), for messages
  StageCommand command;
  // The folders (NAME-KEY) of other missing stages whose outputs its command reads ({cache}/...).
  std::vector<std::string> needs;
  std::string folderName() const { return name + "-" + key; }
};

class PendingStages {
 public:
  // The case the stages collected from now on belong to.
  void setCase(std::string caseName) { case_ = std::move(caseName); }
  // Adds the stage unless it is collected already (two cases may share a stage).
  void add(PendingStage stage);
  const std::vector<PendingStage>& stages() const { return stages_; }
  bool empty() const { return stages_.empty(); }

 private:
  std::string case_;
  std::vector<PendingStage> stages_;
  std::set<std::string> folders_;
};

// The folders (NAME-KEY) of the other stages that `command` reads: its arguments that start with
// kCacheFolder, up to the next '/'.
std::vector<std::string> stageFoldersRead(const StageCommand& command);

}  // namespace iblkit
