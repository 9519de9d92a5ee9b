#include "engine/gl/shading_mode.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

namespace iblkit {
namespace {

TEST(ShadingMode, NamesRoundTrip) {
  const char* names[] = {"unlit", "mirror", "sh",   "irradiance",   "irradiance-ao-bent", "sh-ao",
                         "sh-ao-bent", "prt", "full", "lights", "lights-shadowed", "full-gltf-ao", "full-both-ao"};
  int i = 0;
  for (ShadingMode mode : kShadingModes) {
    EXPECT_EQ(shadingModeName(mode), names[i]);
    EXPECT_EQ(parseShadingMode(names[i]), mode);
    ++i;
  }
  EXPECT_EQ(i, 13);
}

TEST(ShadingMode, UnknownNameIsAnError) {
  EXPECT_EQ(test::errorMessage([] { parseShadingMode("Full"); }),
            "--mode: unknown shading mode 'Full' (expected one of unlit, mirror, sh, irradiance, "
            "irradiance-ao-bent, sh-ao, sh-ao-bent, prt, full, lights, lights-shadowed, full-gltf-ao, full-both-ao)");
}

}  // namespace
}  // namespace iblkit
