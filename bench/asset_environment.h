#pragma once
// The benchmarks' environment maps: a bundled map, IBLKIT_ASSETS/hdri/NAME.exr (default ./assets),
// at its own size, or its bilinear upsampling to 2048 x 1024; each loaded once per program.
#include <cstdlib>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <string>

#include "core/environment_map.h"
#include "core/environment_map_file.h"
#include "core/latlong.h"

namespace iblkit::bench {

// `name`'s map when `width` is its own width (512 for the bundled maps), else the 2048 x 1024 one.
inline const EnvironmentMap& assetEnvironment(const std::string& name, int width) {
  struct Sizes {
    EnvironmentMap asset, large;
  };
  static std::map<std::string, Sizes> maps;
  auto found = maps.find(name);
  if (found == maps.end()) {
    const char* assets = std::getenv("IBLKIT_ASSETS");
    EnvironmentMap asset = loadEnvironmentMap(std::filesystem::path(assets ? assets : "assets") / "hdri" / (name + ".exr"));
    EnvironmentMap large = EnvironmentMap::fromImage(
        latLongFromRadiance(2048, 1024, 1, [&](const glm::vec3& d) { return asset.radiance(d); }), "upsampled");
    found = maps.emplace(name, Sizes{std::move(asset), std::move(large)}).first;
  }
  return width == found->second.asset.width() ? found->second.asset : found->second.large;
}

}  // namespace iblkit::bench
