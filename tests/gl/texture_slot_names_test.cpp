#include "engine/gl/texture_slot_names.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

namespace iblkit {
namespace {

TEST(TextureSlotNames, ListsParseToTheirBits) {
  EXPECT_EQ(parseTextureSlots("all"), unsigned(kAllTextureSlots));
  EXPECT_EQ(parseTextureSlots("none"), 0u);
  EXPECT_EQ(parseTextureSlots("base-color"), unsigned(kSlotBaseColor));
  EXPECT_EQ(parseTextureSlots("normal,emissive"), unsigned(kSlotNormal | kSlotEmissive));
  EXPECT_EQ(parseTextureSlots("base-color,metallic-roughness,normal,occlusion,emissive"),
            unsigned(kAllTextureSlots));
  for (unsigned slots = 0; slots <= kAllTextureSlots; ++slots)
    EXPECT_EQ(parseTextureSlots(textureSlotsName(slots)), slots) << textureSlotsName(slots);
}

TEST(TextureSlotNames, UnknownNameIsAnError) {
  EXPECT_EQ(test::errorMessage([] { parseTextureSlots("normal,albedo"); }),
            "--texture-slots: unknown texture slot 'albedo' (expected one of base-color, metallic-roughness, "
            "normal, occlusion, emissive, all, none)");
  EXPECT_EQ(test::errorMessage([] { parseTextureSlots(""); }),
            "--texture-slots: unknown texture slot '' (expected one of base-color, metallic-roughness, normal, "
            "occlusion, emissive, all, none)");
}

}  // namespace
}  // namespace iblkit
