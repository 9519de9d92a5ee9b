#pragma once
// The visible fraction of a ground's unoccluded light, on a grid over the ground around the objects:
// ground occlusion's coefficient per point (ground_occlusion.h; docs/reference-tracer.md "Ground
// occlusion", "A coefficient per point").
//
// Ground occlusion's estimate at a ground point x is, for any factor beta,
//
//   beta a E_up + sum_s w_s (f V cos - beta a w_y) L / p_s,
//
// unbiased whatever beta is, as long as beta does not depend on the samples it weighs. beta = 1
// takes all the unoccluded light exactly, which removes its noise on the open ground but adds the
// noise of estimating the hidden part in a shadow, where the plain estimate (beta = 0) has almost
// none. Measured with probe rays (docs/benchmarks.md "Ground occlusion on specular grounds"), beta
// = the visible fraction of E_up at x does better than both: under `studio` the control variate's
// loss in the penumbrae became a gain, and the sunny maps gained 6-10% more. This holds that
// fraction, computed once per render: at each node of a grid of kNodes x kNodes over a square of
// half-side kExtent x the objects' bounding radius centred under them, kProbes stratified light
// samples (Hammersley points, the same at every node) of the environment sampler for the upward
// normal, each weighted by its luminance w_y / pdf, and the share of that weight whose shadow ray
// is unblocked. Between the nodes it is interpolated bilinearly; outside the square, and without
// objects, it is 1. It is a deterministic function of the position (no thread count or seed
// changes it).

#include <glm/glm.hpp>
#include <vector>

#include "raytrace/ray_scene.h"
#include "reference/environment_sampler.h"
#include "reference/ground_occlusion.h"

namespace iblkit {

class GroundVisibility {
 public:
  static constexpr int kNodes = 33;
  static constexpr int kProbes = 32;
  static constexpr float kExtent = 4.0f;

  // 1 everywhere.
  GroundVisibility() = default;
  // The grid for `ground`'s objects, traced in `rays` and sampled from `sampler`, in parallel over
  // the rows in the caller's task arena (every core by default); the result does not depend on it.
  GroundVisibility(const GroundOcclusion& ground, const RayScene& rays, const EnvironmentSampler& sampler);

  // The visible fraction at ground point x (its x and z), in [0, 1].
  float at(const glm::vec3& x) const;
  // The value at node (i, j) (i along x, j along z), for the tests.
  float node(int i, int j) const { return values_[static_cast<std::size_t>(j) * kNodes + static_cast<std::size_t>(i)]; }
  bool empty() const { return values_.empty(); }

 private:
  glm::vec2 origin_{0.0f};  // the node (0, 0): x and z
  float spacing_ = 1.0f;
  std::vector<float> values_;  // kNodes x kNodes, row j (z) by row
};

}  // namespace iblkit
