#pragma once
// The environment replaced by point lights (--env-sampling lights; docs/reference-tracer.md
// "Point lights"): the 2^levels median-cut regions of the map (medianCutLights, Debevec 2005),
// each a delta light at its energy centroid carrying the region's irradiance E_i (its summed
// radiance x solid angle). This is Debevec's use of median cut and the seed lectures' "transform the
// environment map into a number of well-selected point light sources": a biased approximation,
// which turns the soft shadow of each region into a hard one (aliasing: N shadows where the map
// casts one soft shadow), converging to the map as N grows.
//
// The integrator picks one light per vertex, light i with probability p_i proportional to the
// luminance of E_i (about 1/N: the regions have equal energy), and weights it by 1 / p_i, so its
// expected contribution at a vertex is the N-light sum  sum_i f(wo, w_i) E_i max(0, n.w_i) V(w_i).

#include <glm/glm.hpp>
#include <vector>

#include "core/distribution.h"
#include "core/environment_lights.h"
#include "core/environment_map.h"

namespace iblkit {

class EnvironmentPointLights {
 public:
  // The median-cut lights of `map` at `levels` (in [0, 12]; std::invalid_argument otherwise).
  EnvironmentPointLights(const EnvironmentMap& map, int levels);

  struct Sample {
    glm::vec3 direction{0.0f};   // unit world direction toward the light
    glm::vec3 irradiance{0.0f};  // E_i / p_i: the light's irradiance over its probability
  };
  // Picks light i with probability p_i from u in [0, 1) (uniformly when the map is black).
  Sample sample(float u) const;

  const std::vector<EnvironmentLight>& lights() const { return lights_; }
  // p_i.
  float probability(int i) const;

  // The N-light sum for a Lambert surface without shadows: sum_i E_i max(0, n.w_i), the
  // irradiance the lights give at unit normal n (for tests and documentation).
  glm::vec3 irradiance(const glm::vec3& n) const;

 private:
  std::vector<EnvironmentLight> lights_;
  PiecewiseConstant1D distribution_;
};

}  // namespace iblkit
