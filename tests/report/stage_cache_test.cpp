#include "report/stage_cache.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

TEST(StageCache, ProducesOnceThenHits) {
  const StageCache cache(test::scratchDir() / "cache");
  int produced = 0;
  auto produce = [&](const fs::path& folder) {
    ++produced;
    EXPECT_TRUE(fs::is_empty(folder));
    std::ofstream(folder / "out.txt") << "result";
  };
  bool hit = true;
  const fs::path first = cache.stage("bake", "0123", produce, &hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(first, cache.root() / "bake-0123");
  EXPECT_TRUE(fs::exists(first / "out.txt"));
  const fs::path second = cache.stage("bake", "0123", produce, &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(second, first);
  EXPECT_EQ(produced, 1);
  cache.stage("bake", "4567", produce);
  EXPECT_EQ(produced, 2);
  EXPECT_EQ(cache.hits(), 1);
  EXPECT_EQ(cache.misses(), 2);
}

TEST(StageCache, AFailedStageLeavesNothing) {
  const StageCache cache(test::scratchDir() / "cache");
  EXPECT_THROW(cache.stage("trace", "89ab",
                           [](const fs::path& folder) {
                             std::ofstream(folder / "partial.exr") << "half";
                             fail(folder / "partial.exr", "the program failed");
                           }),
               Error);
  // Neither the stage nor its temporary folder remains, so the next run starts afresh.
  EXPECT_TRUE(fs::is_empty(cache.root()));
  bool hit = true;
  cache.stage("trace", "89ab", [](const fs::path&) {}, &hit);
  EXPECT_FALSE(hit);
}

}  // namespace
}  // namespace iblkit
