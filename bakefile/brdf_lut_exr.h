#pragma once
// env/brdf_lut.exr of a bake folder (bake_layout.h): the split-sum DFG table (baker/brdf_lut.h
// computes it; R = A, G = B, B = A + B; NoV along x, roughness along y, row 0 first).

#include <filesystem>

#include "core/image.h"

namespace iblkit {

// Writes the table as a 32-bit float RGB OpenEXR (temp name, then rename).
void writeBrdfLutExr(const std::filesystem::path& path, const Image& lut);

// Reads it back. Throws Error("<path>: ...") when the file is missing or not a readable OpenEXR.
Image readBrdfLutExr(const std::filesystem::path& path);

}  // namespace iblkit
