#pragma once
// Heat maps of per-pixel errors: the error through the magma colour map, with a legend bar under
// it (0 at the left, maxValue at the right, white ticks at quarters).

#include <filesystem>
#include <span>

#include "core/image.h"

namespace iblkit {

// A width x (height + legend) linear RGB image: values / maxValue through magma (clamped to
// [0,1]), then a black gap and the legend bar, each max(4, height / 16) rows tall.
Image heatMapImage(std::span<const float> values, int width, int height, float maxValue = 1.0f);

// heatMapImage written as an 8-bit sRGB PNG (tone curve Clamp, exposure 0).
void writeHeatMap(const std::filesystem::path& file, std::span<const float> values, int width, int height,
                  float maxValue = 1.0f);

}  // namespace iblkit
