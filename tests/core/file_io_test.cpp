#include "core/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// How many entries `folder` holds (a temporary left behind shows as one more).
int entries(const std::filesystem::path& folder) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++count;
  return count;
}

TEST(ReadFileBytes, ReadsEveryByte) {
  const std::filesystem::path file = test::scratchDir() / "bytes.bin";
  const std::string text("a\0b\nc", 5);
  writeText(file, text);
  const std::vector<char> bytes = readFileBytes(file);
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), text);
}

TEST(ReadFileBytes, MissingEmptyAndDirectoryAreErrors) {
  const std::filesystem::path dir = test::scratchDir();
  const std::filesystem::path missing = dir / "missing.exr", empty = dir / "empty.bin";
  writeText(empty, "");
  EXPECT_EQ(test::errorMessage([&] { readFileBytes(missing); }),
            missing.string() + ": cannot open: No such file or directory");
  EXPECT_EQ(test::errorMessage([&] { readFileBytes(empty); }), empty.string() + ": empty file (0 bytes)");
  EXPECT_EQ(test::errorMessage([&] { readFileBytes(dir); }), dir.string() + ": not a regular file (a folder); only regular files are read");
}

TEST(WriteAtomically, WritesThroughATemporaryName) {
  const std::filesystem::path file = test::scratchDir() / "out.txt";
  std::filesystem::path seen;
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    seen = temporary;
    EXPECT_FALSE(std::filesystem::exists(file));  // nothing under the final name while writing
    writeText(temporary, "done");
  });
  // A unique name beside the file: "<file>.tmp-XXXXXX".
  EXPECT_EQ(seen.string().rfind(file.string() + ".tmp-", 0), 0u) << seen;
  EXPECT_EQ(seen.string().size(), file.string().size() + 11);
  EXPECT_EQ(contents(file), "done");
  EXPECT_FALSE(std::filesystem::exists(seen));
}

TEST(WriteAtomically, FailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::filesystem::path file = test::scratchDir() / "out.txt";
  writeText(file, "old");
  EXPECT_EQ(test::errorMessage([&] {
              writeAtomically(file, [&](const std::filesystem::path& temporary) {
                writeText(temporary, "half");
                fail(file, "disk full");
              });
            }),
            file.string() + ": disk full");
  EXPECT_EQ(contents(file), "old");
  EXPECT_EQ(entries(file.parent_path()), 1);
}

TEST(WriteAtomically, AFolderUnderTheFinalNameIsAnError) {
  const std::filesystem::path target = test::scratchDir() / "taken";
  std::filesystem::create_directories(target / "inside");
  bool wrote = false;
  EXPECT_EQ(test::errorMessage([&] {
              writeAtomically(target, [&](const std::filesystem::path& temporary) {
                wrote = true;
                writeText(temporary, "x");
              });
            }),
            target.string() + ": is a folder");
  EXPECT_FALSE(wrote);
  EXPECT_EQ(entries(target.parent_path()), 1);
}

// -o /dev/full run as root replaced the device node with a regular file: the rename must never
// replace what is not a regular file.
// The node is made in the scratch folder (a character device like /dev/full where the test may
// make one, else a FIFO): a regression must not replace the machine's /dev/full.
TEST(WriteAtomically, NeverReplacesADeviceNode) {
  const std::filesystem::path device = test::scratchDir() / "full";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    ASSERT_EQ(::mkfifo(device.c_str(), 0666), 0);
  }
  EXPECT_EQ(test::errorMessage([&] {
              writeAtomically(device, [](const std::filesystem::path& temporary) { writeText(temporary, "x"); });
            }),
            device.string() + ": exists and is not a regular file (not replaced)");
  EXPECT_FALSE(std::filesystem::is_regular_file(device));
  // Also when it appears while the temporary is written (checked again before the rename).
  const std::filesystem::path link = device.parent_path() / "late";
  EXPECT_EQ(test::errorMessage([&] {
              writeAtomically(link, [&](const std::filesystem::path& temporary) {
                writeText(temporary, "x");
                std::filesystem::create_symlink(device, link);
              });
            }),
            link.string() + ": exists and is not a regular file (not replaced)");
  EXPECT_FALSE(std::filesystem::is_regular_file(device));
  EXPECT_EQ(entries(link.parent_path()), 2);  // the node and the link; no temporary
}

TEST(WriteAtomically, AMissingFolderNamesTheFile) {
  const std::filesystem::path file = test::scratchDir() / "no" / "out.txt";
  EXPECT_EQ(test::errorMessage([&] { writeAtomically(file, [](const std::filesystem::path&) {}); }),
            file.string() + ": cannot create a temporary file beside it: No such file or directory");
}

}  // namespace
}  // namespace iblkit
