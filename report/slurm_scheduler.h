#pragma once
// Runs the report's missing stages as Slurm job arrays (iblkit-report --scheduler slurm;
// docs/cluster.md). One wave at a time: the stages a collecting report pass found missing
// (pending_stages.h) are submitted as
//   - one array of the bakes,
//   - one array of the engine frames, after the bakes (afterok, --kill-on-invalid-dep=yes),
//   - one array per case of its reference passes, one task per pass (the seeds a local run uses),
// each task running `iblkit-report --stage-task PLAN --task-index I` (stage_plan.h). The scheduler
// then polls squeue with a progress line until every task has left the queue, and checks each
// stage by its folder in the cache, not by the job's state: a task that left no folder failed,
// whatever Slurm says. A failed stage is reported with its log and exit code and is collected
// again by the next pass, so it is resubmitted once; a second failure ends the report with one
// line naming the case.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "report/pending_stages.h"

namespace iblkit {

struct SlurmOptions {
  std::string partition;                         // sbatch --partition; empty: the cluster's default
  std::vector<std::string> sbatchArguments;      // for every array (--time=..., --account=...)
  std::vector<std::string> viewSbatchArguments;  // for the engine frames' array too (--gres=gpu:1)
  std::filesystem::path reportProgram;           // the iblkit-report every task runs
};

class SlurmScheduler {
 public:
  // Finds sbatch, squeue and scontrol (PATH, then /usr/bin and /usr/sbin) and sets USER when it
  // is unset (sbatch wants it). Plans, scripts and task logs go to CACHE/slurm. Throws Error when
  // Slurm's commands are not installed.
  SlurmScheduler(SlurmOptions options, std::filesystem::path cacheRoot);

  // Submits the stages, waits for them and checks their folders (above). Throws Error naming the
  // case when a stage that failed before fails again, or when a stage was submitted three times
  // without ever starting, or when sbatch refuses a submission.
  void runWave(const PendingStages& pending);

  int stagesRun() const { return stagesRun_; }   // stages that Slurm tasks completed so far
  int waves() const { return waves_; }
  int tasksSubmitted() const { return tasksSubmitted_; }

 private:
  struct Task {
    const PendingStage* stage;
    std::string jobId;  // the array's job id
    int index;          // the task's index in the array
    std::filesystem::path log;
  };
  std::string submitArray(const std::string& group, const std::vector<const PendingStage*>& stages,
                          const std::vector<std::string>& after, bool engineFrames, std::vector<Task>& tasks);
  void waitFor(const std::vector<Task>& tasks);
  std::string capture(const std::vector<std::string>& argv, bool keepLog = false);

  SlurmOptions options_;
  std::filesystem::path cacheRoot_, folder_;
  std::string sbatch_, squeue_, scontrol_;
  int waves_ = 0, stagesRun_ = 0, tasksSubmitted_ = 0;
  std::map<std::string, int> failures_, submissions_;  // by stage folder
};

// The state of each task squeue lists ("123_4 RUNNING" lines of `squeue -h -r -o "%i %T"`),
// keyed "JOB_TASK"; lines that are not of that form are skipped.
std::map<std::string, std::string> parseQueueStates(const std::string& output);

// "JobState=FAILED Reason=NonZeroExitCode ExitCode=1:0" from `scontrol -o show job` output: the
// fields a failed task is reported with; empty when none is there.
std::string failedTaskSummary(const std::string& scontrolOutput);

}  // namespace iblkit
