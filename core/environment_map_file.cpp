#include "core/environment_map_file.h"

#include "core/cube_map.h"
#include "core/energy_preserving_repair.h"
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

namespace {
// The lat-long map of `image` (as stored, NaN and Inf already 0) in `format`.
Image latLongOfProbe(Image image, const ExrInfo& info, const std::filesystem::path& file, ProbeFormat format,
                     int latLongWidth) {
  switch (format) {
    case ProbeFormat::LatLong:
      if (info.envmap == EnvmapLayout::Cube) {
        const CubeMap cube = cubeFromExrStrip(image, file);
        const int width = latLongWidth > 0 ? latLongWidth : 4 * cube.size;
        return latLongFromCube(cube, width, kConversionSamplesPerAxis);
      }
      return image;
    case ProbeFormat::MirrorBall:
    case ProbeFormat::Angular: {
      const int width = latLongWidth > 0 ? latLongWidth : 2 * image.height();
      return format == ProbeFormat::MirrorBall ? latLongFromMirrorBall(image, width, kConversionSamplesPerAxis, file)
                                               : latLongFromAngularMap(image, width, kConversionSamplesPerAxis, file);
    }
  }
  fail(file, "unknown environment format");
}
}  // namespace

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& file, ProbeFormat format, int latLongWidth) {
  ExrInfo info;
  Image image = hasExrExtension(file) ? readExr(file, &info, 0, PixelRepair::Keep) : readImage(file, PixelRepair::Keep);
  // NaN and Inf carry no energy to keep; negative values are converted as stored (the resampling
  // of a cube or probe keeps their sum) and repaired on the lat-long map, keeping its integral.
  const PixelRepairCounts nonFinite = repairNonFinitePixels(image);
  Image latLong = latLongOfProbe(std::move(image), info, file, format, latLongWidth);
  const NegativeRadianceRepair negative = repairNegativeRadiance(latLong);
  const std::string summary = environmentRepairSummary(nonFinite, negative);
  if (!summary.empty()) warn(file, summary);
  return EnvironmentMap::fromImage(std::move(latLong), file);
}

}  // namespace iblkit
