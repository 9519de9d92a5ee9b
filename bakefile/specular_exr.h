#pragma once
// env/specular.exr of a bake folder (bake_layout.h): the GGX-prefiltered specular cube chain
// (baker/specular_prefilter.h computes it) as a tiled, mip-mapped OpenEXR cube environment map.

#include <filesystem>
#include <vector>

#include "core/cube_map.h"

namespace iblkit {

// The prefiltered chain and the perceptual roughness of each level.
struct SpecularCube {
  CubeMapLevels levels;
  std::vector<float> roughness;
};

// The string attribute that lists each level's roughness ("0 0.142857 ...").
inline constexpr const char* kRoughnessPerLevelAttribute = "iblkit:roughnessPerLevel";

// Writes the chain as a tiled, mip-mapped OpenEXR cube environment map (32-bit float RGB, envmap =
// cube, each level a W x 6W strip, cubeToExrStrip), with the string attribute
// kRoughnessPerLevelAttribute ("0 0.142857 ..."). OpenEXR's ROUND_DOWN chain of a W x 6W image goes
// on below the 1 x 6 strip (1 x 3, then 1 x 1): those two levels, which are no cube, are box
// downsamples of the last strip (readers use the first log2(W) + 1 levels, as many as the
// attribute lists). Throws Error unless the chain is complete down to 1 x 1 faces.
void writeSpecularCubeExr(const std::filesystem::path& path, const SpecularCube& cube);

// Reads what writeSpecularCubeExr wrote: the first log2(W) + 1 levels, one per roughness listed in
// kRoughnessPerLevelAttribute. Throws Error("<path>: ...") for a missing file, a missing attribute,
// fewer stored levels than listed, or a chain that does not end at 1 x 1 faces.
SpecularCube readSpecularCubeExr(const std::filesystem::path& path);

}  // namespace iblkit
