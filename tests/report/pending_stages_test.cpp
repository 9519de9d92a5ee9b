#include "report/pending_stages.h"

#include <gtest/gtest.h>

#include <fstream>

#include "report/stage_cache.h"
#include "report/stage_run.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// Copies a file into the stage folder; the key hashes the program's and the input's bytes.
StageCommand copyCommand(const std::string& from) {
  return {"/bin/sh", {"-c", "cat \"$1\" > \"$2\"", "sh", from, std::string(kStageFolder) + "/out.txt"}, {}};
}

TEST(PendingStages, ACollectingCacheRecordsMissingStagesAndRunsNothing) {
  const fs::path dir = test::scratchDir();
  std::ofstream(dir / "input.txt") << "scene";
  StageCache cache(dir / "cache");
  PendingStages pending;
  cache.collectInto(&pending);
  pending.setCase("sphere-sky");
  const StageCommand first = copyCommand((dir / "input.txt").string());
  const StageRun a = runStage(cache, "bake-sphere-sky", first);
  EXPECT_TRUE(a.pending);
  EXPECT_EQ(a.folder, cache.folder("bake-sphere-sky", stageKey(first)));
  EXPECT_FALSE(fs::exists(a.folder));  // nothing ran
  // A stage that reads the first one's output needs it.
  const std::string firstFolder = a.folder.filename().string();
  const StageCommand second = copyCommand(std::string(kCacheFolder) + "/" + firstFolder + "/out.txt");
  EXPECT_TRUE(runStage(cache, "view-sphere-sky-sh", second).pending);
  ASSERT_EQ(pending.stages().size(), 2u);
  EXPECT_EQ(pending.stages()[0].key, stageKey(first));
  EXPECT_EQ(pending.stages()[0].caseName, "sphere-sky");
  EXPECT_TRUE(pending.stages()[0].needs.empty());
  EXPECT_EQ(pending.stages()[1].needs, std::vector<std::string>{firstFolder});
  EXPECT_EQ(cache.hits() + cache.misses(), 0);

  // Once the first exists, a collecting pass finds it and collects only the second, which then
  // needs nothing missing.
  cache.collectInto(nullptr);
  EXPECT_FALSE(runStage(cache, "bake-sphere-sky", first).pending);
  PendingStages again;
  cache.collectInto(&again);
  EXPECT_FALSE(runStage(cache, "bake-sphere-sky", first).pending);
  EXPECT_TRUE(runStage(cache, "view-sphere-sky-sh", second).pending);
  ASSERT_EQ(again.stages().size(), 1u);
  EXPECT_EQ(again.stages()[0].name, "view-sphere-sky-sh");
  EXPECT_TRUE(again.stages()[0].needs.empty());
}

TEST(PendingStages, AStageTwoCasesNeedIsCollectedOnce) {
  PendingStages pending;
  pending.setCase("a");
  pending.add({"bake-x", "01", "", copyCommand("in"), {}});
  pending.setCase("b");
  pending.add({"bake-x", "01", "", copyCommand("in"), {}});
  pending.add({"bake-x", "02", "", copyCommand("in"), {}});
  ASSERT_EQ(pending.stages().size(), 2u);
  EXPECT_EQ(pending.stages()[0].caseName, "a");
  EXPECT_EQ(pending.stages()[1].caseName, "b");
}

TEST(PendingStages, TheFoldersACommandReadsAreItsCacheArguments) {
  StageCommand command = copyCommand(std::string(kCacheFolder) + "/bake-a-0123/bake");
  command.arguments.push_back(std::string(kCacheFolder) + "/trace-b-4567");
  command.arguments.push_back("{cachex}/not-a-cache-argument");
  EXPECT_EQ(stageFoldersRead(command), (std::vector<std::string>{"bake-a-0123", "trace-b-4567"}));
}

}  // namespace
}  // namespace iblkit
