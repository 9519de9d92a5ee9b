// End-to-end: no program overwrites or deletes what it did not write (issue 13, "Data loss", and
// crash 4). Each case runs the real program on a small generated scene and checks the exit
// status, the one error line naming the output and the reason, and that the input is untouched.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/small_scene.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using test::shellQuoted;

struct Outcome {
  int status = -1;
  std::string output;
};

Outcome run(const std::string& program, const std::string& arguments) {
  Outcome result;
  result.status = test::runCommand(shellQuoted(test::binDir() / program) + " " + arguments + " 2>&1", &result.output);
  return result;
}

// The output is exactly one line starting "PROGRAM: OUTPUT: " and holding `reason`.
void expectOneLine(const Outcome& run, const std::string& program, const fs::path& output, const std::string& reason) {
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_EQ(run.output.rfind(program + ": " + output.string() + ": ", 0), 0u) << run.output;
  EXPECT_NE(run.output.find(reason), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << run.output;
}

// Not a regular file, in `root`: a character device like /dev/full (major 1, minor 7) where the
// tests may make one (root, as in CI), else a FIFO. Not /dev/full itself: a regression would
// replace the machine's device node (as the old programs did here, run as root).
fs::path specialFile(const fs::path& root) {
  const fs::path node = root / "full";
  if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    EXPECT_EQ(::mkfifo(node.c_str(), 0666), 0);
  }
  return node;
}

bool isSpecial(const fs::path& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0 && (S_ISCHR(info.st_mode) || S_ISFIFO(info.st_mode));
}

TEST(OutputSafety, TraceRefusesToOverwriteTheSceneOrTheMap) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const std::string scene = test::fileBytes(small.scene), map = test::fileBytes(small.map);
  const std::string trace = shellQuoted(small.scene) + " --spp 1 --width 8 --height 6 ";
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(small.scene)), "iblkit-trace", small.scene,
                "output is the same file as the input " + small.scene.string());
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(root / "out.exr") + " --png " + shellQuoted(small.map)),
                "iblkit-trace", small.map, "output is the same file as the input");
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(root / "out.exr") + " --depth " +
                                        shellQuoted(root / "models" / ".." / "scene.json")),
                "iblkit-trace", root / "models" / ".." / "scene.json", "output is the same file as the input");
  // Through a link.
  fs::create_symlink(small.model, root / "link.exr");
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(root / "link.exr")), "iblkit-trace",
                root / "link.exr", "output is the same file as the input " + small.model.string());
  EXPECT_EQ(test::fileBytes(small.scene), scene);
  EXPECT_EQ(test::fileBytes(small.map), map);
  EXPECT_FALSE(fs::exists(root / "out.exr"));
  // Two outputs on one file.
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(root / "out.exr") + " --albedo " +
                                        shellQuoted(root / "out.exr")),
                "iblkit-trace", root / "out.exr", "given as two outputs");
  // And the same command with a new output works.
  const Outcome good = run("iblkit-trace", trace + "-o " + shellQuoted(root / "out.exr"));
  EXPECT_EQ(good.status, 0) << good.output;
  EXPECT_TRUE(fs::is_regular_file(root / "out.exr"));
}

TEST(OutputSafety, ScoreRefusesAHeatMapOnAnInput) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path png = root / "a.png";
  ASSERT_EQ(run("iblkit-info", shellQuoted(small.map) + " --png " + shellQuoted(png)).status, 0);
  const std::string bytes = test::fileBytes(png);
  expectOneLine(run("iblkit-score", shellQuoted(png) + " " + shellQuoted(png) + " --heatmap " + shellQuoted(png)),
                "iblkit-score", png, "output is the same file as the input " + png.string());
  EXPECT_EQ(test::fileBytes(png), bytes);
}

TEST(OutputSafety, InfoRefusesAPreviewOnItsInput) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const std::string bytes = test::fileBytes(small.map);
  expectOneLine(run("iblkit-info", shellQuoted(small.map) + " --png " + shellQuoted(small.map)), "iblkit-info",
                small.map, "output is the same file as the input");
  EXPECT_EQ(test::fileBytes(small.map), bytes);
}

// -o /dev/full, run as root, replaced the device node with a regular file.
TEST(OutputSafety, ADeviceNodeIsNeverReplaced) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path device = specialFile(root);
  ASSERT_TRUE(isSpecial(device));
  const std::string trace = shellQuoted(small.scene) + " --spp 1 --width 8 --height 6 ";
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(device)), "iblkit-trace", device,
                "exists and is not a regular file");
  expectOneLine(run("iblkit-trace", trace + "-o " + shellQuoted(root / "out.exr") + " --png " + shellQuoted(device)),
                "iblkit-trace", device, "exists and is not a regular file");
  expectOneLine(run("iblkit-info", shellQuoted(small.map) + " --png " + shellQuoted(device)), "iblkit-info", device,
                "exists and is not a regular file");
  expectOneLine(run("iblkit-bake", shellQuoted(small.scene) + " --ao-rays 1 -o " + shellQuoted(device)),
                "iblkit-bake", device, "exists and is not a folder");
  expectOneLine(run("iblkit-report", shellQuoted(small.scene) + " --envs " + shellQuoted(small.map) + " -o " +
                                         shellQuoted(device)),
                "iblkit-report", device, "exists and is not a folder");
  EXPECT_TRUE(isSpecial(device));
  EXPECT_FALSE(fs::exists(root / "out.exr"));
}

// It deleted the folder holding the map it was reading.
TEST(OutputSafety, BakeRefusesAFolderThatIsNotABake) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path notes = root / "notes";
  fs::create_directories(notes);
  std::ofstream(notes / "todo.txt") << "mine";
  const std::string bake = shellQuoted(small.scene) + " --ao-rays 2 --specular-samples 1 --lut-size 8 -o ";
  expectOneLine(run("iblkit-bake", bake + shellQuoted(notes)), "iblkit-bake", notes,
                "exists and is not an iblkit bake folder (use --force to replace it)");
  EXPECT_EQ(test::fileBytes(notes / "todo.txt"), "mine");
  // The folder holding the map (and the scene): refused even with --force.
  const std::string map = test::fileBytes(small.map);
  expectOneLine(run("iblkit-bake", bake + shellQuoted(small.map.parent_path()) + " --force"), "iblkit-bake",
                small.map.parent_path(), "output folder holds the input " + small.map.string());
  expectOneLine(run("iblkit-bake", bake + shellQuoted(root) + " --force"), "iblkit-bake", root,
                "output folder holds the input");
  EXPECT_EQ(test::fileBytes(small.map), map);
  // A folder inside an input folder is no input: a bake may go into a new folder beside the scene.
  // --force replaces a folder of another kind; a bake folder is replaced without it.
  Outcome forced = run("iblkit-bake", bake + shellQuoted(notes) + " --force");
  ASSERT_EQ(forced.status, 0) << forced.output;
  EXPECT_FALSE(fs::exists(notes / "todo.txt"));
  EXPECT_TRUE(fs::is_regular_file(notes / "bake.json"));
  forced = run("iblkit-bake", bake + shellQuoted(notes));
  EXPECT_EQ(forced.status, 0) << forced.output;
  // An empty folder is fine.
  fs::create_directories(root / "empty");
  const Outcome empty = run("iblkit-bake", bake + shellQuoted(root / "empty"));
  EXPECT_EQ(empty.status, 0) << empty.output;
}

// Crash 4: an uncaught std::filesystem_error aborted.
TEST(OutputSafety, ReportOntoAnExistingFileIsOneLineAndExitOne) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path file = root / "existing.txt";
  std::ofstream(file) << "keep";
  expectOneLine(run("iblkit-report", shellQuoted(small.scene) + " --envs " + shellQuoted(small.map) + " -o " +
                                         shellQuoted(file)),
                "iblkit-report", file, "exists and is not a folder");
  EXPECT_EQ(test::fileBytes(file), "keep");
  // And onto a folder that is not a report.
  const fs::path notes = root / "notes";
  fs::create_directories(notes);
  std::ofstream(notes / "todo.txt") << "mine";
  expectOneLine(run("iblkit-report", shellQuoted(small.scene) + " --envs " + shellQuoted(small.map) + " -o " +
                                         shellQuoted(notes)),
                "iblkit-report", notes, "exists and is not an iblkit report folder (use --force to replace it)");
  EXPECT_EQ(test::fileBytes(notes / "todo.txt"), "mine");
  // --force: the report writes into the folder (it replaces only its own files).
  const Outcome forced = run("iblkit-report", shellQuoted(small.scene) + " --envs " + shellQuoted(small.map) +
                                                  " --bin " + shellQuoted(test::binDir()) +
                                                  " --width 8 --height 8 --pass-spp 1 --min-passes 2 --max-passes 2"
                                                  " --bench 0 --modes sh --force -o " + shellQuoted(notes));
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_TRUE(fs::is_regular_file(notes / ".iblkit-report"));
  EXPECT_TRUE(fs::is_regular_file(notes / "report.json"));
  EXPECT_EQ(test::fileBytes(notes / "todo.txt"), "mine");
}

}  // namespace
}  // namespace iblkit
