// requireRegularInputFile, readInputFile and requireJsonNesting: special files and oversized
// files are refused by stat before anything opens them, and deep JSON before any parser runs.
#include "core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

TEST(InputFile, ReadsARegularFile) {
  const fs::path file = test::scratchDir() / "a.txt";
  std::ofstream(file) << "abc";
  const std::vector<char> bytes = readInputFile(file, 3);
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "abc");
}

TEST(InputFile, RefusesSpecialFilesWithoutOpeningThem) {
  EXPECT_EQ(test::errorMessage([] { readInputFile("/dev/zero", kMaxBinaryInputBytes); }),
            "/dev/zero: not a regular file (a character device); only regular files are read");
  const fs::path fifo = test::scratchDir() / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // No writer: an open without O_NONBLOCK, or any read, would block here.
  EXPECT_EQ(test::errorMessage([&] { readInputFile(fifo, kMaxBinaryInputBytes); }),
            fifo.string() + ": not a regular file (a FIFO); only regular files are read");
  EXPECT_EQ(test::errorMessage([&] { requireRegularInputFile(fifo.parent_path(), 10); }),
            fifo.parent_path().string() + ": not a regular file (a folder); only regular files are read");
}

TEST(InputFile, RefusesMissingEmptyAndOversizedFiles) {
  const fs::path dir = test::scratchDir();
  EXPECT_EQ(test::errorMessage([&] { readInputFile(dir / "none", 10); }),
            (dir / "none").string() + ": cannot open: No such file or directory");
  std::ofstream(dir / "empty").close();
  EXPECT_EQ(test::errorMessage([&] { readInputFile(dir / "empty", 10); }),
            (dir / "empty").string() + ": empty file (0 bytes)");
  std::ofstream(dir / "big") << "12345";
  EXPECT_EQ(test::errorMessage([&] { readInputFile(dir / "big", 4); }),
            (dir / "big").string() + ": file is 5 bytes, more than the limit of 4");
}

TEST(InputFile, BoundsJsonNestingOutsideStrings) {
  const std::string ok = std::string(kMaxJsonNesting, '[') + std::string(kMaxJsonNesting, ']');
  EXPECT_EQ(test::errorMessage([&] { requireJsonNesting(ok, "a.json"); }), "(no error)");
  const std::string deep = "[" + ok + "]";
  EXPECT_EQ(test::errorMessage([&] { requireJsonNesting(deep, "a.json"); }),
            "a.json: JSON nests arrays and objects more than 256 deep");
  // Brackets inside strings, escaped quotes included, do not count.
  const std::string quoted = "[\"\\\"" + std::string(1000, '[') + "\"]";
  EXPECT_EQ(test::errorMessage([&] { requireJsonNesting(quoted, "a.json"); }), "(no error)");
}

}  // namespace
}  // namespace iblkit
