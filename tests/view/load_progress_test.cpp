#include "engine/view/load_progress.h"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

TEST(LoadProgress, ThePanelLineNamesTheFileTheStepAndHowFarItIs) {
  LoadProgress progress;
  EXPECT_EQ(progress.describe("/models/bunny.glb", 0.04), "opening bunny.glb: reading, 0.0 s ...");
  progress.report("visibility", 45, 100);
  EXPECT_EQ(progress.describe("/models/bunny.glb", 1.24), "opening bunny.glb: visibility 45%, 1.2 s ...");
  progress.report("visibility", 30, 100);  // a worker that finished earlier reports late
  EXPECT_EQ(progress.describe("bunny.glb", 1.3), "opening bunny.glb: visibility 45%, 1.3 s ...");
  progress.report("environment", 1, 4);  // the next step starts from its own count
  EXPECT_EQ(progress.describe("bunny.glb", 2.0), "opening bunny.glb: environment 25%, 2.0 s ...");
  progress.report("environment", 0, 0);
  EXPECT_EQ(progress.describe("bunny.glb", 2.0), "opening bunny.glb: environment 100%, 2.0 s ...");
}

}  // namespace
}  // namespace iblkit
