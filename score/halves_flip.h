#pragma once
// HDR-FLIP between two independent halves of a Monte Carlo image: how visible the noise of one
// half is against the other (docs/report.md "Reference", docs/reference-tracer.md "Noise split").

#include <cstdint>
#include <span>

#include "core/image.h"
#include "score/flip.h"

namespace iblkit {

// The mean over `mask`'s pixels (empty: every pixel) of HDR-FLIP between halves a and b (a as
// FLIP's reference), at `exposures`, or without them at automaticExposureRange of the halves'
// mean. Each half has half the samples of their mean, so this is the FLIP of two images at half
// the spp, an upper view of the mean's own visible noise. Throws Error when the sizes differ or
// the mask scores no pixel.
double halvesMeanFlip(const Image& a, const Image& b, std::span<const std::uint8_t> mask,
                      const ExposureRange* exposures = nullptr);

}  // namespace iblkit
