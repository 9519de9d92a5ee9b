#pragma once
// The pinhole camera every program shares, and the one automatic framing used for scenes
// without a camera. World space is right-handed, +Y up (glTF). The camera looks along `forward`
// with `up` pointing to the top of the image.
//
// Pixel convention (all programs): raster position (px, py) in pixels, (0, 0) the top-left corner
// of the image, y pointing down, pixel (i, j) covering [i, i+1) x [j, j+1) with its centre at
// (i + 0.5, j + 0.5). Normalised device coordinates are x = 2 px / W - 1, y = 1 - 2 py / H, so
// NDC (-1, 1) is the top-left corner, as with OpenGL's projection matrix and a framebuffer read
// back with row 0 at the top (Image's convention). The aspect ratio is W / H, from the image.

#include <glm/glm.hpp>

#include "core/mesh.h"
#include "core/ray.h"

namespace iblkit {

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};     // unit view direction
  glm::vec3 up{0.0f, 1.0f, 0.0f};           // unit, orthogonal to forward
  float yfovRadians = glm::radians(45.0f);  // full vertical field of view
  float znear = 0.1f, zfar = 100.0f;        // clip distances along forward, 0 < znear < zfar

  // A camera at `eye` looking at `target`; `up` only needs to be non-parallel to the view
  // direction (it is made orthogonal to it, as glm::lookAt does). Requires eye != target.
  static Camera lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float yfovRadians,
                       float znear, float zfar);

  // World to camera space (OpenGL convention: the camera looks down -Z), glm::lookAt.
  glm::mat4 viewMatrix() const;
  // viewMatrix() of the world moved by -origin: the camera's position taken relative to `origin`
  // in double, so that a renderer whose vertices are relative to a point near the scene
  // (engine/gl/render_space.h) keeps the precision of the scene's own size however far from the
  // world's origin it stands. viewMatrix(0) is viewMatrix() up to the rounding of the position.
  glm::mat4 viewMatrix(const glm::dvec3& origin) const;
  // Camera space to clip space, glm::perspective (NDC depth in [-1, 1]); aspect = width / height.
  glm::mat4 projectionMatrix(float aspect) const;
  // The ray from the camera position through raster position `rasterPos` (see the pixel
  // convention above) of a width x height image; consistent with projectionMatrix: every point of
  // the ray projects back to rasterPos. Pass (i + 0.5, j + 0.5) for the centre of pixel (i, j).
  Ray primaryRay(const glm::vec2& rasterPos, int width, int height) const;  // unit direction
};

// Camera::primaryRay for every ray of one width x height image, with the per-image terms (the
// orthonormal basis, tan(fov / 2), the aspect) computed once; the same rays, bit for bit
// (primaryRay itself goes through this).
class PrimaryRays {
 public:
  PrimaryRays(const Camera& camera, int width, int height);
  Ray operator()(const glm::vec2& rasterPos) const;

 private:
  glm::vec3 position_, forward_;
  glm::vec3 right_, up_;  // the camera's right and true up, scaled by aspect tan(fov / 2) and tan(fov / 2)
  float toNdcX_, toNdcY_;  // 2 / width, 2 / height
};

// Clip distances for a camera at `position` viewing `bounds`: with d the distance to the bounds'
// centre and r its radius, znear = 0.01 max(d, r) and zfar = d + 20 r, so the default ground of
// a .json scene (10 r wide) stays inside. A far/near ratio of at most 2100 keeps depth precise.
struct ClipPlanes {
  float znear, zfar;
};
ClipPlanes clipPlanesFor(const glm::vec3& position, const Bounds& bounds);

// The automatic framing for scenes without a camera: a 45 degree vertical field of view, looking
// at the bounds' centre from the +Z side, 20 degrees above the horizon, at the distance where the
// bounding sphere fills the smaller of the two fields of view less a 10% margin
// (d = 1.1 r / sin(fov_min / 2)); clip planes from clipPlanesFor. Every point inside the bounds
// then projects inside the image. Empty or zero-size bounds are framed as a unit sphere.
Camera frameBounds(const Bounds& bounds, float aspect);

}  // namespace iblkit
