#include "engine/gl/shading_mode.h"

namespace iblkit {

std::string_view shadingModeName(ShadingMode mode) { return enumNameOf(kShadingModeNames, mode); }

ShadingMode parseShadingMode(std::string_view name) {
  return parseEnumName(kShadingModeNames, name, "--mode", "shading mode");
}

}  // namespace iblkit
