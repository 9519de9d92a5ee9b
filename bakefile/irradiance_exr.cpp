#include "bakefile/irradiance_exr.h"

#include "core/image_io.h"

namespace iblkit {

void writeIrradianceCubeExr(const std::filesystem::path& path, const CubeMap& irradiance) {
  writeExr(path, cubeToExrStrip(irradiance), {.pixelType = PixelType::Float, .envmap = EnvmapLayout::Cube});
}

}  // namespace iblkit
