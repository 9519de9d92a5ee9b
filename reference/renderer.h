#pragma once
// The tile renderer: camera samples per pixel, averaged with a box or Gaussian filter (by filter
// importance sampling, pixel_filter.h), over TBB-parallel
// 16 x 16 tiles. Each sample's random numbers depend only on (seed, pixel, sample index)
// (PixelSampler), and each pixel is summed by one task in sample order, so the images are
// identical for a given seed whatever the thread count.

#include <cstdint>
#include <functional>

#include "core/camera.h"
#include "core/image.h"
#include "reference/integrator.h"
#include "reference/pass_sum.h"
#include "reference/pixel_filter.h"

namespace iblkit {

inline constexpr int kTileSize = 16;
// The most threads a render takes (TBB crashes on an arena of 70,000).
inline constexpr int kMaxRenderThreads = 1024;

inline constexpr float kDefaultTextureFootprint = 0.5f;

// The camera ray cone of a width x height image through `camera`: width 0 at the eye, spread
// `footprint` pixels' angular size (Akenine-Möller et al. 2019, eq. 30, small-angle form), and the
// differentials of PrimaryRays' direction per `footprint` pixels along x and y, which set the first
// hit's texture footprint (textureFootprintFromDifferentials; the spread sets the rest of the path's).
RayCone cameraRayCone(const Camera& camera, int height, float footprint);

struct RenderSettings {
  int width = 0, height = 0;
  // Samples per pixel; with timeSeconds > 0, the size of each pass.
  int samplesPerPixel = 64;
  // The index of the first sample: a pass of a split render takes samples firstSample ..
  // firstSample + samplesPerPixel - 1 (passSamples, pass_sum.h).
  int firstSample = 0;
  // > 0: render passes of samplesPerPixel until this many seconds have passed (at least one).
  double timeSeconds = 0.0;
  std::uint32_t seed = 0;
  int threads = 0;                                // 0: all hardware threads, at most kMaxRenderThreads
  PixelFilterKind filter = PixelFilterKind::Box;  // pixel_filter.h
  // The texture footprint in pixels: the step of the camera rays' differentials and the camera
  // ray cone's spread as a fraction of the pixel's angular size at the image centre
  // (2 tan(fov / 2) / height) (docs/reference-tracer.md "Texture filtering"). The default, half a
  // pixel, is the report's engine frame: 2 x 2 supersampled, so its derivatives, and so its texture
  // levels, are those of half an output pixel. 0 reads the finest level everywhere.
  float textureFootprint = kDefaultTextureFootprint;
};

struct RenderResult {
  Image beauty;             // mean radiance, alpha 1
  Image albedo, normal;     // mean first-hit base colour and shading normal (0 where nothing is hit)
  Image depth;              // mean distance to the first hit, metres, grey (0 where nothing is hit)
  Image mask;               // coverage of non-ground objects, grey in [0, 1]
  Image variance;           // per channel variance of the beauty pixel's mean (sample variance / n)
  Image bentNormal;         // ao: normalised mean unoccluded direction (0 where none)
  // Mean radiance after at most one scattering event (CameraSample::direct; summed in double, not
  // in the exact pass sums, so it is not in --sum files): beauty - direct is the indirect light.
  Image direct;
  // The beauty's exact sums, of which beauty and variance are the mean and its variance
  // (pass_sum.h): what a pass of a split render writes (--sum) for the merge.
  PassSum sum;
  int samplesPerPixel = 0;  // samples actually taken
  double seconds = 0.0;
  std::uint64_t rays = 0;  // closest-hit and shadow rays traced
};

// Called after each tile from whichever thread finished it, serialised: the fraction done
// (of the samples, or of the time budget) and the seconds elapsed.
using RenderProgress = std::function<void(double fraction, double seconds)>;

// Renders through `camera`; pixel (i, j) averages primary rays through raster positions
// (i, j) + PixelFilter(settings.filter).sample(u): u uniform in the pixel for the box filter, or
// spread over the neighbours by the Gaussian's density (filter importance sampling).
// Throws Error("render: ...") for sizes outside 1..kMaxImageSide, sample indices beyond
// kMaxSamplesPerPixel or a negative thread count.
RenderResult render(const Integrator& integrator, const Camera& camera, const RenderSettings& settings,
                    const RenderProgress& progress = {});

}  // namespace iblkit
