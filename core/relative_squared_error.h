#pragma once
// The per-channel term of the relative MSE (score/image_metrics.h), in core because the scorer and
// the viewer's difference view (shaders/difference_heatmap.frag, which reads kRelMseEpsilon from the
// generated shared_constants.glsl) must compute the same one.

namespace iblkit {

// (test - ref)^2 / (ref^2 + epsilon). epsilon = 0.01 keeps near-black reference pixels from
// dominating (as in the denoising literature, e.g. Rousselle et al. 2011); it is documented in
// docs/scoring.md.
inline constexpr double kRelMseEpsilon = 0.01;
inline double relativeSquaredError(double reference, double test) {
  return (test - reference) * (test - reference) / (reference * reference + kRelMseEpsilon);
}

}  // namespace iblkit
