#pragma once
// Dominant lights of an environment map (docs/dominant-lights.md): the two ways iblkit turns a
// lat-long map into a few lights that the engine can shadow and the reference can sample.
//
//  - Median cut (Debevec, "A Median Cut Algorithm for Light Probe Sampling", SIGGRAPH 2005):
//    2^levels axis-aligned texel rectangles of equal energy (luminance x solid angle), each split
//    along its longer side measured in solid angle, at the energy median. Each region becomes a
//    light at its energy centroid carrying the region's summed radiance x solid angle. The regions
//    tile the whole map: they are the whole map, there is no residual.
//  - Sun extraction (as Blender's EEVEE Next does with its world "sun threshold"): texels whose
//    luminance is above a threshold form connected regions (8-connected, wrapping in longitude);
//    the brightest become disk lights. A light carries only the radiance above the threshold, so
//    the residual map (the map with each of its texels clamped to the threshold's level) plus the
//    lights integrate to the map exactly.
//
// Directions are world directions (the map's rotation applied) and every radiometric quantity has
// the map's intensity applied, like EnvironmentMap's texel accessors; residual images are stored
// like the map itself (rotation and intensity not applied), so that an EnvironmentMap made from
// one with the map's rotation and intensity is the residual in world space.
#include <glm/glm.hpp>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/environment_map.h"
#include "core/image.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

enum class EnvironmentLightKind { Sun, MedianCut };

struct EnvironmentLight {
  EnvironmentLightKind kind = EnvironmentLightKind::Sun;
  // Unit world direction toward the light: the normalised sum of its texels' directions weighted
  // by luminance x solid angle (the energy centroid).
  glm::vec3 direction{0.0f, 1.0f, 0.0f};
  // Sum over its texels of (radiance carried) x (texel solid angle): the irradiance it gives a
  // surface facing it when it is small (Debevec's "power"), per RGB channel.
  glm::vec3 irradiance{0.0f};
  // Its solid angle (sr), and the angular radius of the disk with that solid angle,
  // 2 pi (1 - cos r) = solidAngle: the penumbra's source size for the engine's shadows.
  // MedianCut: the sum of its texels' solid angles. Sun: the solid angle of the uniform disk whose
  // spread matches that of the energy it carries (its mean cosine to `direction`, each texel's own
  // extent included): a thresholded region is larger than the sun inside it, and the disk of the
  // same spread is what gives the right irradiance across a surface's horizon (sunIrradiance;
  // docs/dominant-lights.md). A single texel gives its own solid angle.
  float solidAngle = 0.0f;
  float angularRadius = 0.0f;
  // irradiance / solidAngle: the uniform radiance of that disk.
  glm::vec3 radiance{0.0f};
  // Its texels in the stored map: the rectangle [x0, x1) x [y0, y1) (MedianCut), or the bounding
  // box of the region (Sun; x1 may exceed the width when the region wraps in longitude).
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  // SH9 projection (spherical_harmonics.h) of the radiance the light removes from the map, world
  // space: the map's SH9 minus the first K suns' sh9 is the SH9 of the map with only those K taken
  // out (SH is linear), so the engine can change K without a new bake.
  SphericalHarmonics9 sh9;
};

// Median-cut regions of `map`: 2^levels lights (fewer only when a region is a single texel and
// cannot be split), kind MedianCut, in the order the cut produces them. levels in [0, 12]; throws
// std::invalid_argument otherwise.
std::vector<EnvironmentLight> medianCutLights(const EnvironmentMap& map, int levels);

// The bake's median-cut levels unless told otherwise: 16 regions.
inline constexpr int kDefaultMedianCutLevels = 4;

// The automatic threshold's peak-to-mean ratio k (automaticSunThreshold). 32 since 2026-12-07
// (64 before): docs/dominant-lights.md "The automatic threshold" gives the demo's measurements.
inline constexpr float kSunPeakToMean = 32.0f;
// The widest sun, 10 degrees in radians (SunExtractionOptions::maxAngularRadius).
inline constexpr float kMaxSunAngularRadius = 0.17453293f;

struct SunExtractionOptions {
  // Luminance (intensity applied) above which texels belong to a light. <= 0: automatic,
  // automaticSunThreshold(map, peakToMean).
  float threshold = 0.0f;
  float peakToMean = kSunPeakToMean;
  // The most lights kept, brightest (largest irradiance luminance) first.
  int maxLights = 4;
  // Regions carrying less than this fraction of the map's energy stay in the residual.
  float minEnergyFraction = 0.01f;
  // Regions whose light (the disk of the same spread) is wider than this (radians) are no sun and
  // stay in the residual: a bright cap of sky, which SH9 holds, not a compact source to shadow.
  float maxAngularRadius = kMaxSunAngularRadius;
  // Whether ExtractedSuns::residual gets the residual image (a copy of the map with the suns'
  // texels replaced); without it only residualTexels (computeEnvironmentStages turns a map it owns
  // into the residual in place: a 16384 x 8192 map's copy is 2 GiB).
  bool residualImage = true;
};

struct ExtractedSuns {
  std::vector<EnvironmentLight> suns;  // kind Sun, brightest first
  // The map without the suns (stored like the map: rotation and intensity not applied), the same
  // size; lights + residual integrate to the map exactly.
  // Empty when options.residualImage is false: then residualTexels alone say what differs.
  Image residual;
  // The texels the suns took (index y * width + x) with their value in the residual: the
  // residual is the map with these replaced.
  std::vector<std::pair<std::size_t, glm::vec4>> residualTexels;
  float threshold = 0.0f;  // the threshold used (intensity applied)
};

// The suns of `map`: the texels with luminance above the threshold form regions, connected through
// their 8 neighbours, across the longitude seam (column W-1 touches column 0) and around each pole
// (all the texels of the top row touch at +Y, those of the bottom row at -Y). A region's light
// carries texel x (1 - t / luminance) of each of its texels (chroma kept); the residual keeps
// texel x t / luminance. The options.maxLights regions of largest irradiance luminance that carry
// at least options.minEnergyFraction of the map's energy (sum of luminance x solid angle) and are
// at most options.maxAngularRadius wide become lights; the texels of the others stay whole in the
// residual. So residual + lights == map. Throws std::invalid_argument for a non-finite threshold,
// maxLights < 0, minEnergyFraction outside [0, 1], maxAngularRadius < 0 or NaN, or peakToMean < 1
// (when automatic).
ExtractedSuns extractSuns(const EnvironmentMap& map, const SunExtractionOptions& options = {});

// The automatic sun threshold (docs/dominant-lights.md): the largest t with
//   t = peakToMean x mean over the sphere of min(luminance, t),
// so the residual's brightest texel is peakToMean times the residual's mean luminance: the part
// of the map SH9 cannot hold (a peak far above its surroundings) goes to the lights, what is
// left has a bounded dynamic range. Intensity applied, scale-invariant. A map whose brightest
// texel is within peakToMean of its mean gets peakToMean x mean (>= the brightest: no sun); a map
// black but for less than 1/peakToMean of the sphere gets 0 (every lit texel is a light's).
// Exact (the root of a piecewise-linear function of t over the sorted luminances), O(N log N).
// Throws std::invalid_argument unless peakToMean >= 1.
float automaticSunThreshold(const EnvironmentMap& map, float peakToMean = kSunPeakToMean);

// Irradiance that `light`, taken as a disk of uniform radiance light.radiance and angular radius
// light.angularRadius centred on light.direction, gives a surface of unit normal n:
// light.radiance x uniformDiskIrradiance(dot(n, direction), angularRadius) (core/disk_irradiance.h:
// pi sin^2 r cos(theta) above the horizon, the exact clipped-disk formula across it, 0 below).
// The engine's GLSL twin and the reference's biased mode evaluate the same.
glm::vec3 sunIrradiance(const EnvironmentLight& light, const glm::vec3& n);

// What a bake folder's env/lights.json holds (bakefile/environment_lights_json.h) and the engine
// draws: the extracted suns and the median-cut regions of the same map.
struct EnvironmentLights {
  std::vector<EnvironmentLight> suns;
  float sunThreshold = 0.0f;
  std::vector<EnvironmentLight> medianCut;
  int medianCutLevels = 0;
};

}  // namespace iblkit
