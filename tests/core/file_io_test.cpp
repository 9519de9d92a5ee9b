#include "core/file_io.h"

#include <gtest/gtest.h>

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
  EXPECT_EQ(seen.string(), file.string() + ".tmp");
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
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(WriteAtomically, RenameFailureIsAnError) {
  // A non-empty directory under the final name cannot be replaced by a file.
  const std::filesystem::path target = test::scratchDir() / "taken";
  std::filesystem::create_directories(target / "inside");
  EXPECT_EQ(test::errorMessage([&] {
              writeAtomically(target,
                              [](const std::filesystem::path& temporary) { writeText(temporary, "x"); });
            }),
            target.string() + ": cannot rename taken.tmp: Is a directory");
  EXPECT_FALSE(std::filesystem::exists(target.string() + ".tmp"));
}

}  // namespace
}  // namespace iblkit
