#include "core/environment_map_file.h"

#include "core/cube_map.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/light_probe.h"

namespace iblkit {

namespace {
// Supersampling per axis for the conversions: 2x2 is enough for box-filtered resampling at equal
// resolution, and keeps a 2k map's conversion under a second.
constexpr int kConversionSamplesPerAxis = 2;

bool hasExrExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".exr";
}
}  // namespace

ProbeFormat parseProbeFormat(const std::string& name, const std::string& what) {
  return parseEnumName(kProbeFormatNames, name, what, "environment format");
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& file, ProbeFormat format, int latLongWidth) {
  ExrInfo info;
  Image image = hasExrExtension(file) ? readExr(file, &info) : readImage(file);
  switch (format) {
    case ProbeFormat::LatLong:
      if (info.envmap == EnvmapLayout::Cube) {
        const CubeMap cube = cubeFromExrStrip(image, file);
        const int width = latLongWidth > 0 ? latLongWidth : 4 * cube.size;
        return EnvironmentMap::fromImage(latLongFromCube(cube, width, kConversionSamplesPerAxis), file);
      }
      return EnvironmentMap::fromImage(std::move(image), file);
    case ProbeFormat::MirrorBall:
    case ProbeFormat::Angular: {
      const int width = latLongWidth > 0 ? latLongWidth : 2 * image.height();
      Image latLong = format == ProbeFormat::MirrorBall
                          ? latLongFromMirrorBall(image, width, kConversionSamplesPerAxis, file)
                          : latLongFromAngularMap(image, width, kConversionSamplesPerAxis, file);
      return EnvironmentMap::fromImage(std::move(latLong), file);
    }
  }
  fail(file, "unknown environment format");
}

}  // namespace iblkit
