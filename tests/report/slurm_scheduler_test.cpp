#include "report/slurm_scheduler.h"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

TEST(SlurmScheduler, ReadsTaskStatesFromSqueue) {
  // squeue -h -r -o "%i %T": one task per line, array tasks as JOB_TASK; anything else is skipped.
  const auto states = parseQueueStates(
      "21_0 RUNNING\n21_1 PENDING\n  22_10 COMPLETING  \n23 RUNNING\n21_[2-4] PENDING\nslurm_load_jobs error\n");
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states.at("21_0"), "RUNNING");
  EXPECT_EQ(states.at("21_1"), "PENDING");
  EXPECT_EQ(states.at("22_10"), "COMPLETING");
}

TEST(SlurmScheduler, SummarisesAFailedTask) {
  EXPECT_EQ(failedTaskSummary("JobId=48 ArrayJobId=48 ArrayTaskId=0 JobName=iblkit-trace UserId=root(0) "
                              "JobState=FAILED Reason=NonZeroExitCode Dependency=(null) ExitCode=1:0 RunTime=00:00:01"),
            "JobState=FAILED Reason=NonZeroExitCode ExitCode=1:0");
  EXPECT_EQ(failedTaskSummary("slurm_load_jobs error: Invalid job id specified"), "");
}

}  // namespace
}  // namespace iblkit
