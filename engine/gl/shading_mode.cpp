#include "engine/gl/shading_mode.h"

#include <string>

#include "core/error.h"

namespace iblkit {

std::string_view shadingModeName(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Unlit:
      return "unlit";
    case ShadingMode::Mirror:
      return "mirror";
    case ShadingMode::Sh:
      return "sh";
    case ShadingMode::ShAo:
      return "sh-ao";
    case ShadingMode::ShAoBent:
      return "sh-ao-bent";
    case ShadingMode::Prt:
      return "prt";
    case ShadingMode::Full:
      return "full";
  }
  return "unknown";
}

ShadingMode parseShadingMode(std::string_view name) {
  std::string expected;
  for (ShadingMode mode : kShadingModes) {
    if (shadingModeName(mode) == name) return mode;
    expected += (expected.empty() ? "" : ", ") + std::string(shadingModeName(mode));
  }
  fail("--mode", "unknown shading mode '" + std::string(name) + "' (expected one of " + expected + ")");
}

}  // namespace iblkit
