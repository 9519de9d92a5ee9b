#include "report/stage_run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& file) {
  std::ifstream stream(file);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// A stage whose program fails leaves no stage folder, but keeps its log beside the stage folders,
// where the error message points; the same stage run again and succeeding removes that log.
TEST(StageRun, AFailedStageKeepsItsLogWhereTheMessageSays) {
  const fs::path root = test::scratchDir();
  const StageCache cache(root / "cache");
  const fs::path marker = root / "ready";
  // Fails, saying why, until the marker exists.
  const StageCommand command{"/bin/sh",
                             {"-c", "test -f '" + marker.string() + "' || { echo 'input.exr: broken'; exit 3; }"},
                             {}};
  const fs::path kept = cache.folder("check", stageKey(command)).string() + ".failed.log";
  try {
    runStage(cache, "check", command);
    FAIL() << "the stage did not fail";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "/bin/sh: exited with status 3: input.exr: broken (log: " + kept.string() + ")");
  }
  // The log as runProgram writes it: the command line, then what the program printed.
  const std::string log = fileText(kept);
  EXPECT_EQ(log.rfind("$ /bin/sh -c ", 0), 0u) << log;
  EXPECT_TRUE(log.ends_with("\ninput.exr: broken\n")) << log;
  EXPECT_FALSE(fs::exists(cache.folder("check", stageKey(command))));
  std::ofstream(marker) << "";
  const StageRun run = runStage(cache, "check", command);
  EXPECT_TRUE(fs::exists(run.folder / "log.txt"));
  EXPECT_FALSE(fs::exists(kept));
}

}  // namespace
}  // namespace iblkit
