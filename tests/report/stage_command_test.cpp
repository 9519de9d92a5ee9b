#include "report/stage_command.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "report/stage_run.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// A command over real files (the key hashes the program's and the inputs' bytes).
StageCommand exampleCommand(const fs::path& dir) {
  const fs::path input = dir / "input.txt";
  std::ofstream(input) << "scene";
  return {"/bin/sh",
          {"-c", "cat \"$1\" > \"$2\"", "sh", input.string(), std::string(kStageFolder) + "/out.txt"},
          {input}};
}

TEST(StageCommand, TheFoldersReplaceThePlaceholders) {
  StageCommand command = exampleCommand(test::scratchDir());
  command.arguments.push_back(std::string(kCacheFolder) + "/bake-0123/bake");
  const std::vector<std::string> argv = stageArgv(command, "/cache", "/cache/stage.tmp-1");
  ASSERT_EQ(argv.size(), 7u);
  EXPECT_EQ(argv[0], "/bin/sh");
  EXPECT_EQ(argv[4], command.arguments[3]);
  EXPECT_EQ(argv[5], "/cache/stage.tmp-1/out.txt");
  EXPECT_EQ(argv[6], "/cache/bake-0123/bake");
}

TEST(StageCommand, EveryArgumentIsInTheKey) {
  const StageCommand command = exampleCommand(test::scratchDir());
  const std::string key = stageKey(command);
  EXPECT_EQ(stageKey(command), key);
  for (std::size_t i = 0; i < command.arguments.size(); ++i) {
    StageCommand changed = command;
    changed.arguments[i] += "x";
    EXPECT_NE(stageKey(changed), key) << "argument " << i;
  }
  StageCommand extra = command;
  extra.arguments.push_back("--verbose");
  EXPECT_NE(stageKey(extra), key);
  StageCommand otherProgram = command;
  otherProgram.program = "/bin/cat";
  EXPECT_NE(stageKey(otherProgram), key);
}

TEST(StageCommand, TheInputFilesBytesAreInTheKey) {
  const StageCommand command = exampleCommand(test::scratchDir());
  const std::string key = stageKey(command);
  std::ofstream(command.inputFiles[0]) << "scene, edited";
  EXPECT_NE(stageKey(command), key);
}

TEST(StageRun, TheKeyIgnoresTheFolderTheStageRunsIn) {
  // Two caches in different folders: the same command has the same key, so the same stage name,
  // though each ran in its own temporary folder; the recorded command names the real one.
  const fs::path dir = test::scratchDir();
  const StageCommand command = exampleCommand(dir);
  const StageCache first(dir / "first"), second(dir / "second");
  const StageRun a = runStage(first, "copy", command), b = runStage(second, "copy", command);
  EXPECT_EQ(a.folder.filename(), "copy-" + stageKey(command));
  EXPECT_EQ(b.folder.filename(), a.folder.filename());
  std::ifstream output(a.folder / "out.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(output), {}), "scene");
  EXPECT_NE(a.command.find((first.root() / ("copy-" + stageKey(command) + ".tmp-")).string()),
            std::string::npos)
      << a.command;
  EXPECT_EQ(runStage(first, "copy", command).folder, a.folder);
  EXPECT_EQ(first.hits(), 1);
  EXPECT_EQ(first.misses(), 1);
}

}  // namespace
}  // namespace iblkit
