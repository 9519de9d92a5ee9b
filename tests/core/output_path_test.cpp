// checkOutputs (core/output_path.h): an output is refused when it is an input (by device and
// inode, through any path), lies in an input folder, is a device node, or is an existing folder
// of another kind without --force; a replaced folder output must not hold an input.
#include "core/output_path.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

const OutputFolderKind kBake{"iblkit bake folder", {"bake.json"}};

TEST(CheckOutputs, NewPathsAndOtherFilesPass) {
  const fs::path root = test::scratchDir();
  std::ofstream(root / "in.exr") << "x";
  std::ofstream(root / "old.exr") << "y";
  EXPECT_NO_THROW(checkOutputs({root / "in.exr"}, {root / "new.exr", root / "old.exr", ""}));
  EXPECT_NO_THROW(checkOutputs({root / "in.exr"}, {}, {OutputFolder(root / "bake", kBake)}));
}

TEST(CheckOutputs, AnOutputThatIsAnInputIsRefused) {
  const fs::path root = test::scratchDir();
  fs::create_directories(root / "a");
  std::ofstream(root / "in.exr") << "x";
  fs::create_hard_link(root / "in.exr", root / "hard.exr");
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({root / "in.exr"}, {root / "a/../in.exr"}); }),
            (root / "a/../in.exr").string() + ": output is the same file as the input " + (root / "in.exr").string());
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({root / "in.exr"}, {root / "hard.exr"}); }),
            (root / "hard.exr").string() + ": output is the same file as the input " + (root / "in.exr").string());
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({root / "a"}, {root / "a" / "new.png"}); }),
            (root / "a" / "new.png").string() + ": output is inside the input folder " + (root / "a").string());
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({}, {root / "x.exr", root / "a/../x.exr"}); }),
            (root / "a/../x.exr").string() + ": given as two outputs");
}

TEST(CheckOutputs, OnlyRegularFilesAndFoldersAreReplaced) {
  const fs::path device = "/dev/null";  // checkOutputs writes nothing
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({}, {device}); }),
            device.string() + ": exists and is not a regular file (not replaced)");
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({}, {}, {OutputFolder(device, kBake)}); }),
            device.string() + ": exists and is not a folder");
  const fs::path root = test::scratchDir();
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({}, {root}); }), root.string() + ": is a folder");
}

TEST(CheckOutputs, AFolderOfAnotherKindNeedsForceAndAReplacedFolderHoldsNoInput) {
  const fs::path root = test::scratchDir();
  fs::create_directories(root / "notes");
  std::ofstream(root / "notes" / "todo.txt") << "mine";
  fs::create_directories(root / "bake");
  std::ofstream(root / "bake" / "bake.json") << "{}";
  fs::create_directories(root / "empty");
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({}, {}, {OutputFolder(root / "notes/", kBake)}); }),
            (root / "notes").string() + ": exists and is not an iblkit bake folder (use --force to replace it)");
  EXPECT_NO_THROW(checkOutputs({}, {}, {OutputFolder(root / "notes", kBake)}, true));
  EXPECT_NO_THROW(checkOutputs({}, {}, {OutputFolder(root / "bake", kBake)}));
  EXPECT_NO_THROW(checkOutputs({}, {}, {OutputFolder(root / "empty", kBake)}));
  const fs::path map = root / "notes" / "todo.txt";
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({map}, {}, {OutputFolder(root, kBake)}, true); }),
            root.string() + ": output folder holds the input " + map.string() + " (it would be deleted)");
  // A folder the program writes into (not replaced) may hold an input.
  EXPECT_NO_THROW(checkOutputs({map}, {}, {OutputFolder(root / "notes", kBake, false)}, true));
  EXPECT_EQ(test::errorMessage([&] { checkOutputs({root / "bake"}, {}, {OutputFolder(root / "bake", kBake)}); }),
            (root / "bake").string() + ": output folder is the input " + (root / "bake").string());
}

}  // namespace
}  // namespace iblkit
