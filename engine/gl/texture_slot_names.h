#pragma once
// The spellings of the material texture slots (core/texture.h's TextureSlot bits) for
// iblkit-view --texture-slots and the viewer's panel: the glTF slot names in kebab case.
#include <string>
#include <string_view>

#include "core/enum_names.h"
#include "core/texture.h"

namespace iblkit {

inline constexpr EnumName<TextureSlot> kTextureSlotNames[] = {{kSlotBaseColor, "base-color"},
                                                              {kSlotMetallicRoughness, "metallic-roughness"},
                                                              {kSlotNormal, "normal"},
                                                              {kSlotOcclusion, "occlusion"},
                                                              {kSlotEmissive, "emissive"}};

// The TextureSlot bits of `list`: comma-separated names of kTextureSlotNames, or "all", or "none"
// (no texture: every material shows its factors). Throws Error("<what>: unknown texture slot 'x'
// (expected one of base-color, ..., all, none)").
unsigned parseTextureSlots(std::string_view list, const std::string& what = "--texture-slots");

// The names of the slots in `slots`, comma-separated in table order; "all" / "none" for those sets.
std::string textureSlotsName(unsigned slots);

}  // namespace iblkit
