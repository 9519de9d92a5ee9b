#include "score/halves_flip.h"

#include "core/error.h"
#include "score/image_metrics.h"

namespace iblkit {

double halvesMeanFlip(const Image& a, const Image& b, std::span<const std::uint8_t> mask,
                      const ExposureRange* exposures) {
  if (a.width() != b.width() || a.height() != b.height()) fail("halvesMeanFlip", "halves differ in size");
  ExposureRange bracket;
  if (exposures) {
    bracket = *exposures;
  } else {
    Image mean(a.width(), a.height());
    for (std::size_t i = 0; i < a.pixelCount(); ++i)
      mean.pixels()[i] = 0.5f * (a.pixels()[i] + b.pixels()[i]);
    bracket = automaticExposureRange(mean);
  }
  return maskedMean(hdrFlip(a, b, bracket).error, mask);
}

}  // namespace iblkit
