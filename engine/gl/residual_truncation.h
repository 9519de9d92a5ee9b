#pragma once
// What SH9 truncates of the residual's irradiance, as one cube (docs/engine.md "Lights"): per
// texel of the residual's brute-force irradiance cube, the cube's value minus the residual SH9's
// irradiance along the texel's centre direction, clamped at 0 as sphericalHarmonics9Irradiance
// (shaders/sh9.glsl) clamps it. The lights modes add AO times this cube along the visibility
// cone's axis (mesh.vert residualTruncationAt, per vertex): one lookup, instead of a lookup of the
// irradiance cube and an SH9 evaluation, which cost about 9 ms of a 1280 x 720 frame on
// llvmpipe (docs/benchmarks.md). The SH9 is smooth, so interpolating it with the cube's bilinear
// filter moves the result by well under its own truncation error.
#include "core/cube_map.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

// cube - max(E_SH9, 0) texel by texel (alpha 1); an empty cube gives an empty cube.
CubeMap residualTruncationCube(const CubeMap& irradiance, const SphericalHarmonics9& sh9);

}  // namespace iblkit
