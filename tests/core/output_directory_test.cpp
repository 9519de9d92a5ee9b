#include "core/output_directory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "core/error.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void writeText(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

TEST(OutputDirectory, FillsATemporarySiblingThenRenamesIt) {
  const fs::path root = test::scratchDir(), out = root / "nested" / "out";
  fs::path seen;
  writeDirectoryAtomically(out, [&](const fs::path& temporary) {
    seen = temporary;
    EXPECT_EQ(temporary.parent_path(), out.parent_path());
    EXPECT_EQ(temporary.filename().string().rfind("out.tmp-", 0), 0u);
    EXPECT_FALSE(fs::exists(out));
    writeText(temporary / "a.txt", "new");
  });
  EXPECT_FALSE(fs::exists(seen));
  EXPECT_EQ(entries(out), std::vector<std::string>{"a.txt"});
  EXPECT_EQ(entries(root / "nested"), std::vector<std::string>{"out"});
}

TEST(OutputDirectory, ReplacesAnExistingFolderOnlyAfterSuccess) {
  const fs::path root = test::scratchDir(), out = root / "out";
  fs::create_directories(out);
  writeText(out / "old.txt", "old");
  EXPECT_THROW(writeDirectoryAtomically(out / "",
                                        [](const fs::path& temporary) {
                                          writeText(temporary / "half.txt", "half");
                                          fail("stage", "broke");
                                        }),
               Error);
  EXPECT_EQ(entries(root), std::vector<std::string>{"out"});
  EXPECT_EQ(entries(out), std::vector<std::string>{"old.txt"});

  writeDirectoryAtomically(out / "",
                           [](const fs::path& temporary) { writeText(temporary / "new.txt", "new"); });
  EXPECT_EQ(entries(root), std::vector<std::string>{"out"});
  EXPECT_EQ(entries(out), std::vector<std::string>{"new.txt"});
}

TEST(OutputDirectory, AFileInTheWayIsAnError) {
  const fs::path root = test::scratchDir(), out = root / "out";
  writeText(out, "a file");
  bool called = false;
  EXPECT_EQ(
      test::errorMessage([&] { writeDirectoryAtomically(out, [&](const fs::path&) { called = true; }); }),
      out.string() + ": exists and is not a folder");
  EXPECT_FALSE(called);
  EXPECT_EQ(entries(root), std::vector<std::string>{"out"});
}

}  // namespace
}  // namespace iblkit
