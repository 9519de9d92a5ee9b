#pragma once
// Classic full-reference image metrics, restricted to a mask of scored pixels (docs/scoring.md).
// A mask is one byte per pixel (row-major, row 0 at the top), non-zero where the pixel is scored;
// an empty mask scores every pixel. Masks and images must have the same size.

#include <cstdint>
#include <span>
#include <vector>

#include "core/image.h"
#include "core/relative_squared_error.h"

namespace iblkit {

// Mean over scored pixels and RGB channels of (test - reference)^2, on linear values.
double meanSquaredError(const Image& reference, const Image& test, std::span<const std::uint8_t> mask = {});

// Relative MSE: mean over scored pixels and RGB channels of relativeSquaredError
// (core/relative_squared_error.h), (test - ref)^2 / (ref^2 + epsilon).
double relativeMeanSquaredError(const Image& reference, const Image& test,
                                std::span<const std::uint8_t> mask = {});
// Per pixel, the mean over RGB of relativeSquaredError (for heat maps).
std::vector<float> relativeSquaredErrorMap(const Image& reference, const Image& test);

// PSNR in dB of a linear MSE with a peak value of 1 (display white): 10 log10(1 / mse).
// Identical images give +infinity.
double peakSignalToNoiseRatio(double meanSquaredError);

// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image Quality Assessment: From Error Visibility to
// Structural Similarity", eq. 13 with the 11x11 Gaussian window of sigma 1.5, K1 = 0.01,
// K2 = 0.03, L = 1) on the luminance of the tone-mapped images (tone_curve.h, the default
// ToneMapping, so values in [0,1]); the mean of the SSIM map over scored pixels. The window is
// clamped at the image borders, so every pixel has a value.
double structuralSimilarity(const Image& reference, const Image& test,
                            std::span<const std::uint8_t> mask = {});

// The luminance-weighted mean relative error over scored pixels: sum |L_test - L_ref| / sum L_ref
// (Rec.709 luminance of the linear values); 0 when the scored reference is black. Unlike relMSE it
// weighs each pixel by its brightness, so it reads as "the image is x% off".
double meanRelativeLuminanceError(const Image& reference, const Image& test,
                                  std::span<const std::uint8_t> mask = {});

// The number of pixels `mask` scores in an image of `pixelCount` pixels (all of them when empty).
std::size_t scoredPixelCount(std::span<const std::uint8_t> mask, std::size_t pixelCount);

// The mean of per-pixel values over scored pixels (used for FLIP maps). Throws Error when the
// mask scores no pixel.
double maskedMean(std::span<const float> values, std::span<const std::uint8_t> mask = {});

}  // namespace iblkit
