#include "core/texture.h"

#include <cmath>

namespace iblkit {

glm::mat3 TextureTransform::matrix() const {
  // KHR_texture_transform README: translation * rotation * scale, with
  // rotation = mat3(cos, sin, 0, -sin, cos, 0, 0, 0, 1) read row by row, i.e. u' = cos u + sin v,
  // v' = -sin u + cos v (a counter-clockwise rotation of the image in uv space, whose v points down).
  const float c = std::cos(rotation), s = std::sin(rotation);
  const glm::mat3 translationMatrix(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, offset.x, offset.y, 1.0f);
  const glm::mat3 rotationMatrix(c, -s, 0.0f, s, c, 0.0f, 0.0f, 0.0f, 1.0f);
  const glm::mat3 scaleMatrix(scale.x, 0.0f, 0.0f, 0.0f, scale.y, 0.0f, 0.0f, 0.0f, 1.0f);
  return translationMatrix * rotationMatrix * scaleMatrix;
}

glm::vec2 TextureTransform::apply(glm::vec2 uv) const {
  if (identity()) return uv;
  return glm::vec2(matrix() * glm::vec3(uv, 1.0f));
}

}  // namespace iblkit
