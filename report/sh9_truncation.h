#pragma once
// SH9's own error on a view (docs/report.md): the error the best possible `sh` frame would still
// have, because nine coefficients cannot hold the irradiance of a map with a sun or small bright
// lights. For every scored pixel's normal n it compares the bake's SH9 irradiance with brute-force
// irradiance (every texel of the environment a small light). On a convex white Lambert object the
// reference is exactly albedo / pi * E(n), so what an `sh` frame gets wrong beyond this is the
// engine's own doing (errorBeyondSh9).

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "core/environment_map.h"
#include "core/image.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

struct Sh9Truncation {
  // sum |lum E_sh9(n) - lum E(n)| / sum lum E(n) over the scored pixels: what an exact `sh` frame
  // would measure as FrameScores::meanRelativeError.
  double meanRelativeError = 0.0;
  // Per pixel, lum E_sh9(n) / lum E(n); 1 where not scored or where E(n) is 0.
  std::vector<float> ratio;
};

// `normals`: world shading normals (iblkit-trace --normal); `mask`: the scored pixels;
// `environment` carries the scene's rotation and intensity. The brute force runs on the map
// averaged down to at most `bruteForceWidth` texels across (power kept). Irradiance is smooth, but
// a sun spread over a coarse texel is not a sun: on `sky` a 128-wide map left 0.7% of apparent
// engine error (errorBeyondSh9), 256 wide 0.2%. Throws Error for mismatched sizes.
Sh9Truncation sh9Truncation(const EnvironmentMap& environment, const SphericalHarmonics9& sh, const Image& normals,
                            std::span<const std::uint8_t> mask, int bruteForceWidth = 256);

// What `frame` gets wrong beyond SH9's own error: d = lum(frame) - ratio * lum(reference) per
// pixel (0 for a frame that is exactly SH9 of the true irradiance), summed over blocks of
// block x block pixels so that the reference's per-pixel noise, which has zero mean, averages out
// while a coherent error (a wrong orientation, scale or coefficient) does not:
// sum over blocks |sum d| / sum lum(reference), over the scored pixels.
double errorBeyondSh9(const Image& reference, const Image& frame, const Sh9Truncation& truncation,
                      std::span<const std::uint8_t> mask, int block = 16);

// SH9's own error on a report case: the scene's environment map as the scene lights it (its
// rotation and intensity) against the SH9 the bake wrote (BAKE/env/sh9.json), on `normals` over
// `mask` (the reference's pass 0 layer and scored pixels).
Sh9Truncation caseSh9Truncation(const std::filesystem::path& sceneFile,
                                const std::filesystem::path& environmentFile,
                                const std::filesystem::path& bake, const Image& normals,
                                std::span<const std::uint8_t> mask);

// A lat-long map averaged down by a power-of-two factor per axis so it is at most maxWidth wide;
// each output texel is the solid-angle-weighted mean of its block, so every block's power is kept.
Image averageLatLongDown(const Image& latLong, int maxWidth);

}  // namespace iblkit
