#include "report/engine_frames.h"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit {
namespace {

// iblkit-view --bench with several modes prints a line per mode; each mode's is its own, a mode
// whose name begins another's (lights, lights-shadowed) included.
TEST(EngineFrames, EachModeReadsItsOwnMedianFrameTime) {
  const std::string output =
      "iblkit-view: device: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6, 320x180, 4 "
      "sample(s), texture slots all (0 textures, anisotropy 1), median of 5 frames\n"
      "  lights-shadowed cpu 91.25 ms  gpu 3.00 ms\n"
      "  sh              cpu 61.66 ms  gpu 2.77 ms\n"
      "  irradiance-ao-bent cpu 12 ms  gpu 2.86 ms\n"
      "  lights          cpu 49.89 ms  gpu 3.22 ms\n";
  EXPECT_DOUBLE_EQ(parseMedianMilliseconds(output, "sh"), 61.66);
  EXPECT_DOUBLE_EQ(parseMedianMilliseconds(output, "lights"), 49.89);
  EXPECT_DOUBLE_EQ(parseMedianMilliseconds(output, "lights-shadowed"), 91.25);
  EXPECT_DOUBLE_EQ(parseMedianMilliseconds(output, "irradiance-ao-bent"), 12.0);
  EXPECT_TRUE(std::isnan(parseMedianMilliseconds(output, "full")));
  EXPECT_TRUE(std::isnan(parseMedianMilliseconds(output, "ao")));
  EXPECT_TRUE(std::isnan(parseMedianMilliseconds("", "sh")));
}

}  // namespace
}  // namespace iblkit
