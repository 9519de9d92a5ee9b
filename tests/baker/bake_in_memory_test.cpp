#include "baker/bake_in_memory.h"

#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "support/small_scene.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// The in-memory bake says how far it is: the vertices' visibility, then the environment's stages,
// each step ending at done == total; and nothing at all asked of it when no one listens.
TEST(BakeInMemory, ReportsItsStepsUpToTheirTotals) {
  const test::SmallScene small = test::writeSmallScene(test::scratchDir() / "bake-in-memory-progress");
  std::mutex mutex;
  std::vector<std::string> order;  // the steps in the order they first report
  std::map<std::string, std::pair<std::size_t, std::size_t>> last;  // step: (most done, total)
  InMemoryBakeOptions options;
  options.aoRays = 8;
  options.progress = [&](const char* step, std::size_t done, std::size_t total) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!last.count(step)) order.push_back(step);
    auto& [most, all] = last[step];
    most = std::max(most, done);
    all = total;
  };
  const BakedScene bake = bakeInMemory(small.scene, options);
  ASSERT_EQ(order, (std::vector<std::string>{"visibility", "environment"}));
  std::size_t vertices = 0;
  for (const Mesh& mesh : bake.scene.meshes) vertices += mesh.vertexCount();
  EXPECT_EQ(last["visibility"], std::make_pair(vertices, vertices));
  EXPECT_GT(last["environment"].second, 0u);
  EXPECT_EQ(last["environment"].first, last["environment"].second);

  // Stages given: only the visibility is baked, and only it reports.
  order.clear();
  last.clear();
  options.environmentStages = &bake.env;
  bakeInMemory(small.scene, options);
  EXPECT_EQ(order, (std::vector<std::string>{"visibility"}));
}

}  // namespace
}  // namespace iblkit
