#pragma once
// The numbers the report gives for one engine frame against its path-traced reference, and the
// reference's own error (docs/report.md). Scored pixels are those that see geometry: the sky is
// drawn from the same map by both programs and is trivially right.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/image.h"
#include "score/flip.h"
#include "score/score_images.h"

namespace iblkit {

// A frame's scores: every metric of scoreImages but MSE and PSNR, which mean little on HDR values.
using FrameScores = ImageScores;

// Scores `test` against `reference` (same size) over `mask` with HDR-FLIP at the given exposure
// bracket, which the caller fixes per reference so that every mode is scored the same way
// (scoreImages; a frame with NaN or infinite values has only invalidPixels set, and fails).
// `flip` (optional) receives the FLIP error map.
FrameScores scoreFrame(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                       const ExposureRange& exposures, FlipErrorMap* flip = nullptr);

// Pixels that see geometry: a depth layer (distance along the camera ray, 0 where nothing is hit,
// iblkit-trace --depth) above 0.
std::vector<std::uint8_t> geometryMask(const Image& depth);

// The mask without its rim: a pixel stays when it and its four neighbours are set (pixels on the
// image border lose the neighbours outside). A rim pixel mixes object and sky in proportions each
// program's pixel filter decides, which is not the shading being scored.
std::vector<std::uint8_t> erodeMask(std::span<const std::uint8_t> mask, int width, int height);

// The pixel-wise mean of two images of the same size.
Image averageImages(const Image& a, const Image& b);

}  // namespace iblkit
