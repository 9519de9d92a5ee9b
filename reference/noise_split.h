#pragma once
// The noise of a render, measured on the render itself: two independent halves (disjoint seeds),
// whose difference estimates the relMSE of their mean without a ground truth (core/halves_noise.h),
// split by what the camera ray hits first (docs/reference-tracer.md "Noise split"). iblkit-trace
// --noise-split; the report's references use the same estimate (docs/report.md "Reference").

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/camera.h"
#include "reference/integrator.h"
#include "reference/renderer.h"

namespace iblkit {

// The estimated relMSE of the mean over one class of pixels: `pixels` of them, relMse the mean
// over them, share their part of the relMSE over every geometry pixel (relMse x pixels / the sum
// over the classes); 0 and 0 for a class without pixels.
struct NoiseShare {
  std::size_t pixels = 0;
  double relMse = 0.0, share = 0.0;
};

struct NoiseSplit {
  RenderResult a, b;  // the halves: seeds 2 seed and 2 seed + 1, half the samples each
  RenderResult mean;  // their mean: the image of every sample (layers averaged, variance of the mean)
  // halvesRelMseEstimate over the pixels that see geometry (depth > 0: the sky a camera ray sees is
  // the map itself, exact), and by first hit: object (mask >= 0.5) and ground (the other ones).
  double relMse = 0.0;
  NoiseShare object, ground;
  // The same pixels' estimate by path depth (halvesPartRelMseEstimate): the light after one
  // scattering event (RenderResult::direct) and the rest; their shares of the two's sum (which is
  // relMse but for twice their covariance). pixels: the geometry pixels.
  NoiseShare direct, indirect;
  std::vector<std::uint8_t> geometry;  // one byte per pixel, 1 where depth > 0; empty when none is
};

// Renders the two halves with `settings` but seeds 2 settings.seed and 2 settings.seed + 1 (so the
// halves of seeds s and s' never share one), settings.samplesPerPixel / 2 samples each, and with
// settings.timeSeconds > 0 half the time each. Throws std::invalid_argument when
// settings.samplesPerPixel is odd; Error("render: ...") as render() does.
NoiseSplit renderNoiseSplit(const Integrator& integrator, const Camera& camera,
                            const RenderSettings& settings, const RenderProgress& progress = {});

// The split as JSON: spp, seconds, relMseEstimate, halvesMeanFlip (given: computed by the scorer,
// score/halves_flip.h), byFirstHit {object, ground: {pixels, relMse, share}}, byDepth {direct,
// indirect: {pixels, relMse, share}}.
void writeNoiseSplitJson(const std::filesystem::path& file, const NoiseSplit& split, double halvesMeanFlip);

}  // namespace iblkit
