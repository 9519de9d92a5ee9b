#pragma once
// Light-probe images (square photographs of the whole sphere of directions) and their conversion
// to lat-long. Both formats put the direction +Z at the image centre, +X to the right and +Y up,
// and -Z on the rim of the unit disk inscribed in the square image; pixels outside the disk hold
// no direction and are ignored. Normalised image coordinates: x = 2u - 1 (right), y = 1 - 2v (up),
// with u, v in [0, 1] and row 0 at the top. Derivations: docs/conventions.md.
//
// Mirror ball: a mirrored sphere photographed orthographically by a camera on +Z looking down -Z.
// The ball's normal at image point (x, y) is n = (x, y, sqrt(1 - x^2 - y^2)) and the view ray
// (0, 0, -1) reflects to d = (2 n_z x, 2 n_z y, 2 n_z^2 - 1): the point at image radius
// r = sin(theta / 2) sees the direction at angle theta from +Z.
// Angular map (Debevec's light-probe format, Radiance's angmap.cal): image radius proportional to
// the angle from +Z, r = acos(d_z) / pi, so (x, y) = (d_x, d_y) * acos(d_z) / (pi * sqrt(d_x^2 + d_y^2)).

#include <filesystem>
#include <glm/glm.hpp>

#include "core/image.h"

namespace iblkit {

// Direction (any non-zero length) -> (u, v) in the mirror-ball image. -Z, whose image is the
// whole rim, gives the rim point (u, v) = (1, 0.5). A zero vector gives the centre.
glm::vec2 mirrorBallUv(const glm::vec3& direction);
// (u, v) in the mirror-ball image -> unit direction; points on or outside the rim give -Z.
glm::vec3 mirrorBallDirection(const glm::vec2& uv);

// Direction (any non-zero length) -> (u, v) in the angular map. -Z gives the rim point
// (u, v) = (1, 0.5). A zero vector gives the centre.
glm::vec2 angularMapUv(const glm::vec3& direction);
// (u, v) in the angular map -> unit direction; points on or outside the rim give -Z.
glm::vec3 angularMapDirection(const glm::vec2& uv);

// Probe -> width x width/2 lat-long image (docs/conventions.md), each texel the mean of
// samplesPerAxis^2 directions looked up bilinearly in the probe. Bilinear taps whose pixel centre
// lies outside the disk are left out and the rest renormalised; in the sliver at the rim where
// all four taps are outside, the nearest tap is used. Throws Error("<file>: mirror-ball probe is
// WxH, expected a square image") (or "angular map is ...") unless the probe is square and not
// empty; std::invalid_argument unless width is even and >= 2 and samplesPerAxis >= 1.
Image latLongFromMirrorBall(const Image& probe, int width, int samplesPerAxis,
                            const std::filesystem::path& fileForErrors);
Image latLongFromAngularMap(const Image& probe, int width, int samplesPerAxis,
                            const std::filesystem::path& fileForErrors);

}  // namespace iblkit
