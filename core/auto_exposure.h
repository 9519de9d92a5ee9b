#pragma once
// Automatic exposure from the key of an image (Reinhard et al. 2002, "Photographic tone
// reproduction"): the log-average luminance exp(mean(log L)) of its pixels, and the exposure in
// stops that brings it to the middle grey 0.18. The report's thumbnails (report/case_pictures.h)
// and the viewer's automatic exposure (docs/viewer.md) use these; scores never do (they are on
// linear HDR).
#include <cstdint>
#include <optional>
#include <span>

#include "core/image.h"

namespace iblkit {

inline constexpr float kMiddleGrey = 0.18f;

// The log-average luminance of the pixels of `image` with a non-zero `mask` entry (every pixel
// when `mask` is empty) whose luminance is positive and finite: black pixels (a background
// without sky, alpha 0) and NaN do not count. Unset when none does.
std::optional<float> logAverageLuminance(const Image& image, std::span<const std::uint8_t> mask = {});

// log2(kMiddleGrey / logAverageLuminance), clamped to [-16, 16] stops; 0 when no pixel counts.
float keyExposure(const Image& image, std::span<const std::uint8_t> mask = {});

}  // namespace iblkit
