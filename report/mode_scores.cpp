#include "report/mode_scores.h"

#include <string>

#include "report/frame_scores.h"

namespace iblkit {

std::vector<FlipErrorMap> scoreModes(const Reference& reference, const std::vector<Image>& frames,
                                     CaseResult& result) {
  std::vector<FlipErrorMap> flipMaps(result.modes.size());
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    ModeResult& modeResult = result.modes[m];
    if (!modeResult.failure.empty()) continue;
    modeResult.scores =
        scoreFrame(reference.image, frames[m], reference.mask, result.flipExposures, &flipMaps[m]);
    if (modeResult.scores.invalidPixels > 0)
      modeResult.failure = std::to_string(modeResult.scores.invalidPixels) + " NaN or infinite pixel values";
  }
  return flipMaps;
}

}  // namespace iblkit
