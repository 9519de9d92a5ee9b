#pragma once
// env/irradiance.exr of a bake folder (bake_layout.h): the environment's brute-force irradiance
// cube (baker/irradiance_cube.h computes it), for comparison with the SH9 irradiance.

#include <filesystem>

#include "core/cube_map.h"

namespace iblkit {

// Writes the cube as a single-level OpenEXR cube map (float, W x 6W strip, OpenEXR's envmap
// attribute). Throws Error naming the file when it cannot be written.
void writeIrradianceCubeExr(const std::filesystem::path& path, const CubeMap& irradiance);

}  // namespace iblkit
