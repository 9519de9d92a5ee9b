#include "score/score_inputs.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {

namespace {

std::string sizeText(const Image& image) {
  return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

bool isPng(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".png";
}

// Reads an image keeping its values, and refuses NaN and infinities: no metric means anything with them.
Image readChecked(const std::filesystem::path& file) {
  Image image = readImage(file, PixelRepair::Keep);
  const PixelRepairCounts invalid = countInvalidPixels(image);
  if (const std::size_t count = invalid.nan + invalid.inf; count > 0)
    fail(file, std::to_string(count) +
                   (count == 1 ? " NaN or infinite pixel value" : " NaN or infinite pixel values"));
  return image;
}

bool hasPartialAlpha(const Image& image) {
  return std::any_of(image.pixels().begin(), image.pixels().end(),
                     [](const glm::vec4& p) { return p.a < 1.0f; });
}

}  // namespace

ScoreInputs loadScoreInputs(const std::filesystem::path& referenceFile, const std::filesystem::path& testFile,
                            const std::filesystem::path& maskFile) {
  ScoreInputs inputs;
  inputs.reference = readChecked(referenceFile);
  inputs.test = readChecked(testFile);
  if (inputs.test.width() != inputs.reference.width() || inputs.test.height() != inputs.reference.height())
    fail(testFile, "image is " + sizeText(inputs.test) + ", reference is " + sizeText(inputs.reference));
  if (isPng(referenceFile) != isPng(testFile))
    fail(testFile, "cannot compare an LDR (.png) image with an HDR image");
  inputs.highDynamicRange = !isPng(referenceFile);

  const std::size_t count = inputs.reference.pixelCount();
  if (!maskFile.empty()) {
    const Image mask = readChecked(maskFile);
    if (mask.width() != inputs.reference.width() || mask.height() != inputs.reference.height())
      fail(maskFile, "mask is " + sizeText(mask) + ", images are " + sizeText(inputs.reference));
    const bool useAlpha = hasPartialAlpha(mask);
    inputs.mask.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const glm::vec4& p = mask.pixels()[i];
      inputs.mask[i] = (useAlpha ? p.a : luminance(glm::vec3(p))) > 0.5f;
    }
  } else if (hasPartialAlpha(inputs.test)) {
    inputs.mask.resize(count);
    for (std::size_t i = 0; i < count; ++i) inputs.mask[i] = inputs.test.pixels()[i].a > 0.5f;
  }
  if (!inputs.mask.empty() &&
      std::none_of(inputs.mask.begin(), inputs.mask.end(), [](std::uint8_t m) { return m != 0; }))
    fail(maskFile.empty() ? testFile : maskFile, "the mask scores no pixel");
  return inputs;
}

}  // namespace iblkit
