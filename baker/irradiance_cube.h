#pragma once
// env/irradiance.exr: the environment's diffuse irradiance as a small cube map, computed by brute
// force (every texel of the map a light, bruteForceIrradianceCube), to compare the SH9 irradiance
// the engine evaluates against (issue 4: "an irradiance cube map for comparison"). docs/prefilter.md.


#include "core/cube_map.h"
#include "core/environment_map.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

// Lat-long maps wider than this are box-filtered down (2x2 at a time) before the brute-force sum,
// which costs faces x texels: irradiance is so smooth that the sum over a small map is exact to
// well under 1% at 256 x 128 (irradiance_cube_test), and a 2048 x 1024 map would take 64 times as
// long.
inline constexpr int kIrradianceSourceWidth = 256;

// Irradiance E(n) = integral L(w) max(0, n.w) dw (W/m^2 per unit radiance; a white Lambert
// surface reflects E / pi) at the centre of every texel of a size x size cube, rotation and
// intensity applied. Throws std::invalid_argument for size < 1.
CubeMap irradianceCube(const EnvironmentMap& environment, int size);

// How far sh.irradiance(n) is from the cube's brute-force irradiance, over the texel centres, on
// luminance (Rec. 709): the mean and the largest |E_sh - E| / E (texels with E = 0 skipped).
struct IrradianceError {
  float meanRelative = 0.0f;
  float maxRelative = 0.0f;
};
IrradianceError shIrradianceError(const CubeMap& irradiance, const SphericalHarmonics9& sh);

}  // namespace iblkit
