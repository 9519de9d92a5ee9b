#include "baker/irradiance_cube.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/environment_sh.h"
#include "core/image.h"
#include "core/image_io.h"

namespace iblkit {

CubeMap irradianceCube(const EnvironmentMap& environment, int size) {
  if (size < 1) throw std::invalid_argument("irradianceCube: size must be >= 1");
  if (environment.width() <= kIrradianceSourceWidth) return bruteForceIrradianceCube(environment, size);
  // Halved from the map itself, not from a copy of it (a 16384 x 8192 map is 2 GiB).
  Image image = downsample2x(environment.image());
  while (image.width() > kIrradianceSourceWidth) image = downsample2x(image);
  EnvironmentMap small = EnvironmentMap::fromImage(std::move(image), "downsampled environment");
  small.setRotationDegrees(environment.rotationDegrees());
  small.setIntensity(environment.intensity());
  return bruteForceIrradianceCube(small, size);
}

IrradianceError shIrradianceError(const CubeMap& irradiance, const SphericalHarmonics9& sh) {
  IrradianceError error;
  double sum = 0.0;
  int count = 0;
  const int size = irradiance.size;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float exact = luminance(glm::vec3(irradiance.faces[static_cast<std::size_t>(face)].at(x, y)));
        if (!(exact > 0.0f)) continue;
        const glm::vec3 n = cubeDirection(face, (glm::vec2(x, y) + 0.5f) / static_cast<float>(size));
        const float relative = std::abs(luminance(sh.irradiance(n)) - exact) / exact;
        sum += relative;
        ++count;
        error.maxRelative = std::max(error.maxRelative, relative);
      }
  error.meanRelative = count ? static_cast<float>(sum / count) : 0.0f;
  return error;
}

}  // namespace iblkit
