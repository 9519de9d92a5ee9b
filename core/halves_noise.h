#pragma once
// The noise of a Monte Carlo image estimated from two independent halves of it, without a ground
// truth (docs/reference-tracer.md "Noise split", docs/report.md "Reference").

#include <cstdint>
#include <span>

#include "core/image.h"

namespace iblkit {

// The relative MSE of the mean m = (a + b) / 2 of two independent, equally weighted Monte Carlo
// halves a and b of the same image, estimated from their difference: per scored pixel and RGB
// channel ((a - b) / 2)^2 / (m^2 + epsilon) (relativeSquaredError(m, a), epsilon = kRelMseEpsilon),
// averaged. The numerator is an unbiased estimate of var(m): E[(a - b)^2] = var(a) + var(b) =
// 4 var(m). The denominator has m^2 for the unknown truth mu^2, so the ratio is not unbiased: for
// small Gaussian noise of relative variance r = var(m) / mu^2 in a pixel it reads about 3r high,
// but with heavy-tailed pixel noise it reads low, since a half that catches a firefly has a large
// m^2 (tests/reference/noise_split_test.cpp: 9% low at a relMSE of 0.0056, 22% low with fireflies
// at 0.023). It falls to the true relMSE as the noise does. `mask` as in score/image_metrics.h (empty: every pixel).
// Throws Error when the sizes differ or the mask scores no pixel.
double halvesRelMseEstimate(const Image& a, const Image& b, std::span<const std::uint8_t> mask = {});

// The part of that estimate one component of the image carries (the light after one scattering
// event, say, of a = aPart + aRest): per scored pixel and RGB channel ((aPart - bPart) / 2)^2 over
// the whole image's (m^2 + epsilon), m = (a + b) / 2, averaged. The parts of a split add up to the
// whole's estimate but for twice their covariance. Throws Error when the sizes differ or the mask
// scores no pixel.
double halvesPartRelMseEstimate(const Image& aPart, const Image& bPart, const Image& a, const Image& b,
                                std::span<const std::uint8_t> mask = {});

}  // namespace iblkit
