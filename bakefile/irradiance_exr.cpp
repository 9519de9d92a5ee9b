#include "bakefile/irradiance_exr.h"

#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {

void writeIrradianceCubeExr(const std::filesystem::path& path, const CubeMap& irradiance) {
  writeExr(path, cubeToExrStrip(irradiance), {.pixelType = PixelType::Float, .envmap = EnvmapLayout::Cube});
}

CubeMap readIrradianceCubeExr(const std::filesystem::path& path) {
  ExrInfo info;
  const Image strip = readExr(path, &info);
  if (info.envmap != EnvmapLayout::Cube) fail(path, "not an OpenEXR cube map (envmap attribute)");
  return cubeFromExrStrip(strip, path);
}

}  // namespace iblkit
