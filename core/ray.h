#pragma once
// A ray origin + t * direction, shared by the camera (primary rays, unit direction) and the
// Embree ray-query layer (any direction length; t is then in units of that length).

#include <glm/glm.hpp>

namespace iblkit {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
};

}  // namespace iblkit
