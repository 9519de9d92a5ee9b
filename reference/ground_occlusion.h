#pragma once
// Ground occlusion: the direct environment light of a horizontal Lambert ground as its exact
// unoccluded irradiance minus the part the objects hide (issue 16; docs/reference-tracer.md
// "Ground occlusion").
//
// Where the reference's noise is under a bright sky (docs/benchmarks.md, "Where venice's noise
// is"): two thirds in the direct light, most of it on the ground. On a plane whose BRDF f(x) does
// not depend on the directions (a Lambert ground: no specular layer) the direct light splits
// exactly:
//
//   L_direct(x) = f(x) int_{H+} V(x, w) L(w) w_y dw = f(x) (E_up - O(x)),
//   E_up = int_{H+} L(w) w_y dw,       O(x) = int_{H+} (1 - V(x, w)) L(w) w_y dw,
//
// with H+ the upper hemisphere. E_up is one number for the whole plane (the map is at infinity),
// computed once, exactly for the map's bilinear lookups (upperHemisphereIrradiance). Only O is
// estimated, by the same two strategies and the same power-heuristic weights as the plain
// estimate of the direct light (the light samples, and the BRDF ray, which counts where it is
// blocked instead of where it escapes), so the estimate is the plain one with the unoccluded
// light's own noise taken out: f (E_up - sum_s w_s (1 - V) L cos / p_s) against
// f sum_s w_s V L cos / p_s. The ground cannot hide its own upper hemisphere, so 1 - V is zero
// outside the cone a sphere bounding every other triangle subtends at x (coneAt): a light sample
// outside it needs no shadow ray.
//
// It applies where every ground mesh lies in one horizontal plane, so that no ground triangle can
// hide another ground point's sky. Where f depends on the directions (a specular layer) the
// integrator takes the split as a control variate, a E_up plus the estimate of (f V - a) L cos
// (docs/reference-tracer.md "Ground occlusion"; this class is the same for both), and where the
// objects hide at least half of the light, with a coefficient beta on a E_up (ground_visibility.h). A sample's estimate can be negative (where O's samples exceed
// E_up, deep in a shadow); the estimator is unbiased, so their mean is not.

#include <glm/glm.hpp>
#include <optional>

#include "core/environment_map.h"
#include "core/scene.h"

namespace iblkit {

// int_{w_y > 0} L(w) w_y dw for the map's lookups (EnvironmentMap::radiance: bilinear, seamless
// in longitude, clamped at the poles, rotation about +Y and intensity applied), in double: averaged
// over a row of the lat-long grid the bilinear lookup is the interpolation of the rows' texel means,
// piecewise linear in latitude, so the integral is a 1D one over the latitude, taken by 5-point
// Gauss-Legendre quadrature between the rows' centres (the weight's sin cos is smooth there).
glm::vec3 upperHemisphereIrradiance(const EnvironmentMap& map);

class GroundOcclusion {
 public:
  // The technique for `scene` lit by `environment`, or nothing when it does not apply: no ground
  // mesh, or ground meshes whose vertices are not all at one height (within 1e-6 of the scene's
  // size).
  static std::optional<GroundOcclusion> of(const Scene& scene, const EnvironmentMap& environment);

  // E_up (intensity applied).
  const glm::vec3& unoccludedIrradiance() const { return irradianceUp_; }
  float groundHeight() const { return groundHeight_; }
  // The sphere that holds every vertex of the non-ground meshes; a radius < 0 when there is none.
  const glm::vec3& objectsCenter() const { return center_; }
  float objectsRadius() const { return radius_; }

  // The directions from `origin` (a shadow ray's origin on the ground) that an object can block: a
  // cone about `axis` with cos(half-angle) `cosRadius`, -1 (every direction) when `origin` is
  // inside the objects' bounding sphere; `empty` when the scene has no object (nothing blocks).
  struct Cone {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    float cosRadius = -1.0f;
    bool empty = false;
    bool contains(const glm::vec3& w) const { return !empty && glm::dot(w, axis) >= cosRadius; }
  };
  Cone coneAt(const glm::vec3& origin) const;

 private:
  glm::vec3 irradianceUp_{0.0f};
  float groundHeight_ = 0.0f;
  // The sphere that holds every vertex of the scene's non-ground meshes (radius < 0: none).
  glm::vec3 center_{0.0f};
  float radius_ = -1.0f;
};

}  // namespace iblkit
