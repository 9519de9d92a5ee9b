#pragma once
// env/sh9.json of a bake folder (bake_layout.h): the environment's SH9 radiance coefficients
// (core/spherical_harmonics.h's basis and normalisation, named in the file) and the sinc^4
// ringing window's cutoff (core/environment_sh.h, docs/prefilter.md).

#include <filesystem>

#include "core/spherical_harmonics.h"

namespace iblkit {

// Writes `sh`, the coefficients the engine evaluates (already windowed when windowCutoff > 0,
// docs/prefilter.md), with the A_l constants of the irradiance formula and the window cutoff (0:
// none). Temp name, then rename.
// Throws Error("<path>: ...") for non-finite coefficients or when the file cannot be written.
void writeSh9Json(const std::filesystem::path& path, const SphericalHarmonics9& sh, float windowCutoff);

// Reads what writeSh9Json wrote: the coefficients, and the window cutoff into *windowCutoff
// (optional). Throws Error("<path>: ...") for a missing, unreadable or malformed file.
SphericalHarmonics9 readSh9Json(const std::filesystem::path& path, float* windowCutoff = nullptr);

}  // namespace iblkit
