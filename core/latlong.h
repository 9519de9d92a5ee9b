#pragma once
// The latitude-longitude (equirectangular) mapping between directions and image coordinates, with
// the axes of OpenEXR's standard lat-long environment map (ImfEnvmap.h) and continuous texel
// centres. Formulas and the difference from OpenEXR's pixel formula: docs/conventions.md.
//   lon = 2*pi*(0.5 - u), lat = pi*(0.5 - v)
//   d   = (cos(lat) sin(lon), sin(lat), cos(lat) cos(lon))
// so u = 0.5 is +Z, u = 0.25 is +X, u = 0.75 is -X, v = 0 (top row) is +Y; texel (x, y) of a W x H
// image covers u in [x/W, (x+1)/W] and v in [y/H, (y+1)/H], its centre at ((x+0.5)/W, (y+0.5)/H).

#include <functional>
#include <glm/glm.hpp>

#include "core/image.h"

namespace iblkit {

// Any function of a direction that returns linear Rec.709 radiance (an environment, a cube map,
// an analytic test pattern). Directions passed to it are unit length.
using RadianceFunction = std::function<glm::vec3(const glm::vec3& direction)>;

// Direction -> (u, v) in [0, 1]^2. The direction need not be unit length: the formulas are ratios
// of its components (lon = atan2(x, z), lat = atan2(y, hypot(x, z)), robust at the poles where
// asin(y) is not; atan2 is fastAtan2, within 3e-7 radians). A zero vector gives the image centre (+Z); non-finite input gives NaN.
glm::vec2 latLongUv(const glm::vec3& direction);

// (u, v) -> unit direction; u, v outside [0, 1] follow the same formula (u is periodic).
glm::vec3 latLongDirection(const glm::vec2& uv);
// latLongDirection's factors of u alone (sin and cos of the longitude) and of v alone (cos and sin
// of the latitude), for loops over a map's texels that take each column's and each row's once:
// latLongDirection(uv) is latLongDirection(latLongLongitude(uv.x), latLongLatitude(uv.y)), bit for
// bit.
glm::vec2 latLongLongitude(float u);
glm::vec2 latLongLatitude(float v);
inline glm::vec3 latLongDirection(const glm::vec2& longitude, const glm::vec2& latitude) {
  return {latitude.x * longitude.x, latitude.y, latitude.x * longitude.y};
}

// Exact solid angle (steradians) of any texel in row y of a width x height lat-long image:
// (2*pi/width) * (sin(lat_top) - sin(lat_bottom)). All texels of a map sum to 4*pi.
float latLongTexelSolidAngle(int width, int height, int y);

// Bilinear lookup (RGB) between texel centres: u wraps (the first and last columns blend across
// the seam at u = 0 = 1), v is clamped to the centres of the top and bottom rows. The image must
// not be empty. Non-finite uv gives NaN.
glm::vec3 sampleLatLongBilinear(const Image& latLong, const glm::vec2& uv);

// The texel containing uv (u wraps, v clamps). The image must not be empty. Non-finite uv gives NaN.
glm::vec3 sampleLatLongNearest(const Image& latLong, const glm::vec2& uv);

// Renders a width x height lat-long image of `radiance`: each texel is the solid-angle-weighted
// mean of samplesPerAxis^2 stratified samples (weight cos(lat), the density of solid angle in uv).
// Alpha is 1. Throws std::invalid_argument unless width, height and samplesPerAxis are >= 1.
Image latLongFromRadiance(int width, int height, int samplesPerAxis, const RadianceFunction& radiance);

}  // namespace iblkit
