#include "bakefile/brdf_lut_exr.h"

#include "core/image_io.h"

namespace iblkit {

void writeBrdfLutExr(const std::filesystem::path& path, const Image& lut) {
  writeExr(path, lut, {.pixelType = PixelType::Float});
}

Image readBrdfLutExr(const std::filesystem::path& path) { return readExr(path); }

}  // namespace iblkit
