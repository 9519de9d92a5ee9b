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
  // Sum of its texels' solid angles (sr), and the angular radius of the disk with that solid angle,
  // 2 pi (1 - cos r) = solidAngle: the penumbra's source size for the engine's shadows.
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

struct SunExtractionOptions {
  // Luminance (intensity applied) above which texels belong to a light. <= 0: automatic, chosen
  // from the map (docs/dominant-lights.md says how).
  float threshold = 0.0f;
  // The most lights kept, brightest (largest irradiance luminance) first.
  int maxLights = 4;
  // Regions carrying less than this fraction of the map's energy stay in the residual.
  float minEnergyFraction = 0.01f;
};

struct ExtractedSuns {
  std::vector<EnvironmentLight> suns;  // kind Sun, brightest first
  // The map without the suns (stored like the map: rotation and intensity not applied), the same
  // size; lights + residual integrate to the map exactly.
  Image residual;
  float threshold = 0.0f;  // the threshold used (intensity applied)
};

ExtractedSuns extractSuns(const EnvironmentMap& map, const SunExtractionOptions& options = {});

// What a bake folder's env/lights.json holds (bakefile/environment_lights_json.h) and the engine
// draws: the extracted suns and the median-cut regions of the same map.
struct EnvironmentLights {
  std::vector<EnvironmentLight> suns;
  float sunThreshold = 0.0f;
  std::vector<EnvironmentLight> medianCut;
  int medianCutLevels = 0;
};

}  // namespace iblkit
