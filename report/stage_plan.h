#pragma once
// The plan of a job array of stages (docs/cluster.md): a JSON file listing, for each array task,
// the stage it runs (name, key, program, arguments, input files), with the cache folder and the
// folder the commands' relative paths start from. Every task is a hidden mode of iblkit-report,
// `iblkit-report --stage-task PLAN --task-index I`, that runs its stage through runStage
// (stage_run.h), so that a stage run on a node writes the very folder a local run writes: into a
// temporary folder, renamed when whole.

#include <filesystem>
#include <vector>

#include "report/pending_stages.h"

namespace iblkit {

// Writes the plan (atomically) of `stages`, task I running stages[I].
void writeStagePlan(const std::filesystem::path& file, const std::filesystem::path& cacheRoot,
                    const std::vector<PendingStage>& stages);

// The plan's stages, in task order, and its cache folder and working folder. Throws Error naming
// the file when it is unreadable or malformed.
struct StagePlan {
  std::filesystem::path cacheRoot, workingFolder;
  std::vector<PendingStage> stages;
};
StagePlan readStagePlan(const std::filesystem::path& file);

// Runs task `index` of the plan: changes to its working folder and runs the stage through runStage,
// unless it is cached already. Throws Error when the index is out of range, when the stage's key
// today differs from the plan's (a program or an input file changed since it was submitted, so
// its output would land under a key nobody asks for), or when the stage's program fails.
void runStageTask(const std::filesystem::path& plan, int index);

}  // namespace iblkit
