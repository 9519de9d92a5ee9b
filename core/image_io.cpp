// The parts of image loading shared by every format: dispatch by extension, pixel repair and
// the size limit. The formats themselves live in exr_io.cpp, radiance_hdr.cpp and png_io.cpp.
#include "core/image_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace iblkit {

Image readImage(const std::filesystem::path& file, PixelRepair repair) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".exr") return readExr(file, nullptr, 0, repair);
  if (extension == ".hdr" || extension == ".pic") return readRadianceHdr(file, repair);
  if (extension == ".png") return readPng(file, repair);
  fail(file, "unknown image format \"" + extension + "\" (expected .exr, .hdr, .pic or .png)");
}

namespace {

// Counts `value` in `counts` and returns true when it is NaN, infinite or negative.
bool countIfInvalid(float value, PixelRepairCounts& counts) {
  if (value >= 0.0f && value <= std::numeric_limits<float>::max()) return false;  // the common case
  if (std::isnan(value))
    ++counts.nan;
  else if (std::isinf(value))
    ++counts.inf;
  else
    ++counts.negative;
  return true;
}

}  // namespace

PixelRepairCounts countInvalidPixels(const Image& image) {
  PixelRepairCounts counts;
  for (const glm::vec4& pixel : image.pixels())
    for (int c = 0; c < 4; ++c) countIfInvalid(pixel[c], counts);
  return counts;
}

PixelRepairCounts repairNonFinitePixels(Image& image) {
  PixelRepairCounts counts;
  for (glm::vec4& pixel : image.pixels())
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(pixel[c])) {
        ++(std::isnan(pixel[c]) ? counts.nan : counts.inf);
        pixel[c] = 0.0f;
      }
  return counts;
}

std::string pixelRepairSummary(const PixelRepairCounts& counts) {
  std::vector<std::string> parts;
  if (counts.nan) parts.push_back(std::to_string(counts.nan) + " NaN");
  if (counts.inf) parts.push_back(std::to_string(counts.inf) + " Inf");
  if (counts.negative) parts.push_back(std::to_string(counts.negative) + " negative");
  if (parts.empty()) return "";
  std::string list = parts.front();
  for (std::size_t i = 1; i < parts.size(); ++i) list += (i + 1 == parts.size() ? " and " : ", ") + parts[i];
  const bool single = counts.nan + counts.inf + counts.negative == 1;
  return list + (single ? " pixel value set to 0" : " pixel values set to 0");
}

PixelRepairCounts repairPixels(const std::filesystem::path& file, std::span<Image> images) {
  PixelRepairCounts counts;
  for (Image& image : images)
    for (glm::vec4& pixel : image.pixels())
      for (int c = 0; c < 4; ++c)
        if (countIfInvalid(pixel[c], counts)) pixel[c] = 0.0f;
  const std::string summary = pixelRepairSummary(counts);
  if (!summary.empty()) warn(file, summary);
  return counts;
}

void checkImageSize(const std::filesystem::path& file, std::int64_t width, std::int64_t height) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height);
  if (width < 1 || height < 1) fail(file, "zero-size image (" + size + ")");
  if (width > kMaxImagePixels / height)
    fail(file, "image too large (" + size + ", more than " + std::to_string(kMaxImagePixels) + " pixels)");
}

}  // namespace iblkit
