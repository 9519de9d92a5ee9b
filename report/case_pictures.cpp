#include "report/case_pictures.h"

#include <algorithm>
#include <cmath>

#include "core/auto_exposure.h"
#include "core/image_io.h"
#include "report/page_images.h"
#include "score/heat_map.h"

namespace iblkit {

namespace fs = std::filesystem;

float thumbnailExposure(const Image& reference, std::span<const std::uint8_t> mask) {
  return keyExposure(reference, mask);  // the viewer's automatic exposure too (core/auto_exposure.h)
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
  // The reference and every scored frame, linear, for the page's exposure control.
  std::vector<std::pair<std::string, const Image*>> linear = {{"reference", &reference.image}};
  for (std::size_t m = 0; m < result.modes.size(); ++m)
    if (result.modes[m].failure.empty()) linear.push_back({result.modes[m].mode, &frames[m]});
  result.linearImages = "images/" + caseName + "-linear.js";
  writeCaseImagesScript(outDir / result.linearImages, caseName, linear);
}

}  // namespace iblkit
