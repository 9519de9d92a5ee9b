#include "engine/gl/texture_slot_names.h"

#include <vector>

#include "core/error.h"

namespace iblkit {

unsigned parseTextureSlots(std::string_view list, const std::string& what) {
  if (list == "all") return kAllTextureSlots;
  if (list == "none") return 0;
  unsigned slots = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string_view name = list.substr(start, comma == std::string_view::npos ? comma : comma - start);
    bool found = false;
    for (const EnumName<TextureSlot>& entry : kTextureSlotNames)
      if (entry.name == name) {
        slots |= entry.value;
        found = true;
      }
    if (!found) {
      std::vector<std::string> names = enumNames(kTextureSlotNames);
      names.insert(names.end(), {"all", "none"});
      fail(what, unknownNameProblem("texture slot", name, names));
    }
    if (comma == std::string_view::npos) return slots;
    start = comma + 1;
  }
}

std::string textureSlotsName(unsigned slots) {
  slots &= kAllTextureSlots;
  if (slots == kAllTextureSlots) return "all";
  if (slots == 0) return "none";
  std::string names;
  for (const EnumName<TextureSlot>& entry : kTextureSlotNames)
    if (slots & entry.value) {
      // Appended piece by piece: GCC 12 gives a false -Wrestrict on "," + std::string (its bug 105329).
      if (!names.empty()) names += ',';
      names += entry.name;
    }
  return names;
}

}  // namespace iblkit
