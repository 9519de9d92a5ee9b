#include "report/stage_plan.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "report/stage_cache.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

PendingStage copyStage(const std::string& name, const fs::path& input) {
  PendingStage stage{name, "", "sphere-sky",
                     {"/bin/sh", {"-c", "cat \"$1\" > \"$2\"", "sh", input.string(), std::string(kStageFolder) + "/out.txt"}, {input}},
                     {}};
  stage.key = stageKey(stage.command);
  return stage;
}

std::string fileText(const fs::path& file) {
  std::ifstream stream(file);
  return {std::istreambuf_iterator<char>(stream), {}};
}

TEST(StagePlan, ReadsBackWhatItWrote) {
  const fs::path dir = test::scratchDir();
  std::ofstream(dir / "a.txt") << "a";
  const std::vector<PendingStage> stages = {copyStage("trace-s-0", dir / "a.txt"), copyStage("trace-s-1", dir / "a.txt")};
  writeStagePlan(dir / "plan.json", dir / "cache", stages);
  const StagePlan plan = readStagePlan(dir / "plan.json");
  EXPECT_EQ(plan.cacheRoot, fs::absolute(dir / "cache"));
  EXPECT_EQ(plan.workingFolder, fs::current_path());
  ASSERT_EQ(plan.stages.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(plan.stages[i].name, stages[i].name);
    EXPECT_EQ(plan.stages[i].key, stages[i].key);
    EXPECT_EQ(plan.stages[i].caseName, "sphere-sky");
    EXPECT_EQ(plan.stages[i].command.program, stages[i].command.program);
    EXPECT_EQ(plan.stages[i].command.arguments, stages[i].command.arguments);
    EXPECT_EQ(plan.stages[i].command.inputFiles, stages[i].command.inputFiles);
    EXPECT_EQ(stageKey(plan.stages[i].command), stages[i].key);
  }
}

TEST(StagePlan, ATaskRunsItsStageIntoTheCache) {
  const fs::path dir = test::scratchDir();
  std::ofstream(dir / "a.txt") << "a";
  std::ofstream(dir / "b.txt") << "b";
  const std::vector<PendingStage> stages = {copyStage("trace-s-0", dir / "a.txt"), copyStage("trace-s-1", dir / "b.txt")};
  writeStagePlan(dir / "plan.json", dir / "cache", stages);
  runStageTask(dir / "plan.json", 1);
  const fs::path folder = StageCache(dir / "cache").folder(stages[1].name, stages[1].key);
  EXPECT_EQ(fileText(folder / "out.txt"), "b");
  EXPECT_TRUE(fs::exists(folder / "stage.json"));
  EXPECT_FALSE(fs::exists(StageCache(dir / "cache").folder(stages[0].name, stages[0].key)));
  runStageTask(dir / "plan.json", 1);  // cached: nothing to do
}

TEST(StagePlan, ATaskRefusesAnIndexOutsideThePlanAndChangedInputs) {
  const fs::path dir = test::scratchDir();
  std::ofstream(dir / "a.txt") << "a";
  writeStagePlan(dir / "plan.json", dir / "cache", {copyStage("trace-s-0", dir / "a.txt")});
  try {
    runStageTask(dir / "plan.json", 1);
    ADD_FAILURE() << "task 1 of a plan of 1 ran";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "plan.json").string() + ": task 1 is not in the plan (it has 1 stages)");
  }
  std::ofstream(dir / "a.txt") << "edited after submission";
  try {
    runStageTask(dir / "plan.json", 0);
    ADD_FAILURE() << "a stage whose input changed ran";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("changed since it was submitted"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "cache"));
}

TEST(StagePlan, AMalformedPlanIsAnErrorNamingIt) {
  const fs::path dir = test::scratchDir();
  std::ofstream(dir / "plan.json") << R"({"cache": "c", "stages": [{"name": 3}]})";
  try {
    readStagePlan(dir / "plan.json");
    ADD_FAILURE() << "a malformed plan was read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir / "plan.json").string() + ": malformed stage plan", 0), 0u) << e.what();
  }
  std::ofstream(dir / "plan.json") << "not json";
  EXPECT_THROW(readStagePlan(dir / "plan.json"), Error);
  EXPECT_THROW(readStagePlan(dir / "missing.json"), Error);
  EXPECT_THROW(readStagePlan(dir), Error);                // a folder
  EXPECT_THROW(readStagePlan("/dev/zero"), Error);        // a device: refused unread
}

}  // namespace
}  // namespace iblkit
