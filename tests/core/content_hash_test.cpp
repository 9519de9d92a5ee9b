#include "core/content_hash.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(ContentHash, KnownValueAndBoundaries) {
  // FNV-1a 64 of the empty input is the offset basis.
  EXPECT_EQ(ContentHash().hex(), "cbf29ce484222325");
  EXPECT_EQ(ContentHash().add("abc").hex(), ContentHash().add("abc").hex());
  EXPECT_NE(ContentHash().add("abc").hex(), ContentHash().add("abd").hex());
  // Lengths are hashed too, so the split between pieces matters.
  EXPECT_NE(ContentHash().add("ab").add("c").hex(), ContentHash().add("a").add("bc").hex());
  EXPECT_EQ(ContentHash().hex().size(), 16u);
}

TEST(ContentHash, FilesByContent) {
  const auto folder = test::scratchDir();
  std::ofstream(folder / "a.txt") << "same bytes";
  std::ofstream(folder / "b.txt") << "same bytes";
  std::ofstream(folder / "c.txt") << "same bytez";
  EXPECT_EQ(ContentHash().addFile(folder / "a.txt").hex(), ContentHash().addFile(folder / "b.txt").hex());
  EXPECT_NE(ContentHash().addFile(folder / "a.txt").hex(), ContentHash().addFile(folder / "c.txt").hex());
  try {
    ContentHash().addFile(folder / "missing.txt");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (folder / "missing.txt").string() + ": cannot open: No such file or directory");
  }
}

}  // namespace
}  // namespace iblkit
