#include "report/case_pictures.h"

#include <algorithm>
#include <cmath>

#include "core/image_io.h"
#include "score/heat_map.h"

namespace iblkit {

namespace fs = std::filesystem;

float thumbnailExposure(const Image& reference, std::span<const std::uint8_t> mask) {
  std::vector<float> values;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    if (mask[i]) values.push_back(luminance(glm::vec3(reference.pixels()[i])));
  if (values.empty()) return 0.0f;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  const float median = values[values.size() / 2];
  return median > 0.0f ? std::clamp(std::log2(0.18f / median), -16.0f, 16.0f) : 0.0f;
}

void writeCasePictures(const fs::path& outDir, const std::string& caseName, const Reference& reference,
                       const std::vector<Image>& frames, const std::vector<FlipErrorMap>& flipMaps,
                       CaseResult& result) {
  fs::create_directories(outDir / "images");
  result.exposure = thumbnailExposure(reference.image, reference.mask);
  const ToneMapping toneMapping{result.exposure, ToneCurve::AcesFitted};
  result.referenceImage = "images/" + caseName + "-reference.png";
  writePng(outDir / result.referenceImage, reference.image, toneMapping);
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    ModeResult& modeResult = result.modes[m];
    if (!modeResult.failure.empty()) continue;
    modeResult.image = "images/" + caseName + "-" + modeResult.mode + ".png";
    writePng(outDir / modeResult.image, frames[m], toneMapping);
    modeResult.heatMap = "images/" + caseName + "-" + modeResult.mode + "-flip.png";
    writeHeatMap(outDir / modeResult.heatMap, flipMaps[m].error, flipMaps[m].width, flipMaps[m].height);
  }
}

}  // namespace iblkit
