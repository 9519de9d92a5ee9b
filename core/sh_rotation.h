#pragma once
// Rotating SH9 coefficients, for turning the environment without re-projecting it (PRT and the SH
// modes take the rotated coefficients; the transfer vectors stay as baked).
#include "core/spherical_harmonics.h"

namespace iblkit {

// The coefficients of f(R_y(-angle) d) for f = sh: the function turned by +angle about +Y in the
// sense of environment_map.h (what sh showed at +Z appears at +X for +90 degrees). Exact up to
// rounding: each band is closed under rotation, so the rotated basis functions are fitted by
// least squares at 32 directions, which the nine basis functions determine uniquely.
SphericalHarmonics9 rotateShAboutY(const SphericalHarmonics9& sh, float degrees);

}  // namespace iblkit
