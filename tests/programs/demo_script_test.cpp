// End-to-end: scripts/demo.sh, the README's first command after setup, on a fresh folder and again
// on its own output (the report must accept the folder the script filled first with inputs.html
// and maps/). The report is cut to one scene, one map and a few tiny frames so the test is short;
// the demo's own settings are what `make demo` runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

int runDemo(const fs::path& out, std::string* output) {
  const fs::path root = test::assetsDir().parent_path();
  const std::string options =
      "assets/scenes/mirror_sphere.json --envs studio --width 16 --height 8 --pass-spp 1 --min-passes 2 "
      "--max-passes 2 --bench 0";
  return test::runCommand("cd " + test::shellQuoted(root) + " && IBLKIT_DEMO_OUT=" + test::shellQuoted(out) +
                              " IBLKIT_REPORT_OPTIONS='" + options + "' bash scripts/demo.sh " +
                              test::shellQuoted(test::binDir().parent_path()) + " 2>&1",
                          output);
}

TEST(DemoScript, RunsIntoAFreshFolderAndAgainOntoItsOwnOutput) {
  const fs::path out = test::scratchDir() / "demo";
  for (int run = 0; run < 2; ++run) {
    std::string output;
    ASSERT_EQ(runDemo(out, &output), 0) << "run " << run << ":\n" << output;
    EXPECT_TRUE(fs::is_regular_file(out / "inputs.html")) << output;
    EXPECT_TRUE(fs::is_regular_file(out / "report.html")) << output;
    EXPECT_TRUE(fs::is_regular_file(out / "report.json")) << output;
    EXPECT_TRUE(fs::is_regular_file(out / "maps" / "studio.png")) << output;
  }
}

}  // namespace
}  // namespace iblkit
