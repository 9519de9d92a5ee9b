#pragma once
// env/irradiance.exr of a bake folder (bake_layout.h): the environment's brute-force irradiance
// cube (baker/irradiance_cube.h computes it), the engine's `irradiance` modes' diffuse light and
// the SH9 irradiance's yardstick.

#include <filesystem>

#include "core/cube_map.h"

namespace iblkit {

// Writes the cube as a single-level OpenEXR cube map (float, W x 6W strip, OpenEXR's envmap
// attribute). Throws Error naming the file when it cannot be written.
void writeIrradianceCubeExr(const std::filesystem::path& path, const CubeMap& irradiance);
// Reads it back. Throws Error("<file>: ...") for an unreadable file, one whose envmap attribute is
// not cube, or a strip that is not W x 6W; NaN, Inf and negative values are repaired by readExr.
CubeMap readIrradianceCubeExr(const std::filesystem::path& path);

}  // namespace iblkit
