#pragma once
// Frame: a right-handed orthonormal basis (x, y, z) built from one unit vector z, used to move
// directions between world space and a local shading space where z is the surface normal (the
// convention of brdf.h, microfacet.h and sampling.h: cos(theta) = local z).

#include <cmath>
#include <glm/glm.hpp>

namespace iblkit {

struct Frame {
  glm::vec3 x{1.0f, 0.0f, 0.0f};
  glm::vec3 y{0.0f, 1.0f, 0.0f};
  glm::vec3 z{0.0f, 0.0f, 1.0f};

  // The basis around the unit vector z, branch-free and without the singularity at z = (0,0,-1)
  // of Frisvad's construction: Duff et al. 2017, "Building an Orthonormal Basis, Revisited",
  // JCGT 6(1), Listing 3. z = (0,0,1) gives the identity frame.
  static Frame fromZ(const glm::vec3& z) {
    const float sign = std::copysign(1.0f, z.z);
    const float a = -1.0f / (sign + z.z);
    const float b = z.x * z.y * a;
    Frame frame;
    frame.x = glm::vec3(1.0f + sign * z.x * z.x * a, sign * b, -sign * z.x);
    frame.y = glm::vec3(b, sign + z.y * z.y * a, -z.y);
    frame.z = z;
    return frame;
  }

  // World -> local coordinates (the components of v along x, y, z).
  glm::vec3 toLocal(const glm::vec3& v) const { return {glm::dot(v, x), glm::dot(v, y), glm::dot(v, z)}; }
  // Local -> world.
  glm::vec3 toWorld(const glm::vec3& v) const { return x * v.x + y * v.y + z * v.z; }
};

}  // namespace iblkit
