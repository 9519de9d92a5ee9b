#include "engine/gl/residual_truncation.h"

#include <algorithm>

namespace iblkit {

CubeMap residualTruncationCube(const CubeMap& irradiance, const SphericalHarmonics9& sh9) {
  CubeMap truncation = irradiance;
  const float size = float(irradiance.size);
  for (int face = 0; face < 6; ++face) {
    Image& image = truncation.faces[std::size_t(face)];
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const glm::vec3 direction = cubeDirection(face, (glm::vec2(x, y) + 0.5f) / size);
        const glm::vec3 sh = glm::max(sh9.irradiance(direction), glm::vec3(0.0f));
        image.at(x, y) = glm::vec4(glm::vec3(image.at(x, y)) - sh, 1.0f);
      }
  }
  return truncation;
}

}  // namespace iblkit
