#pragma once
// Buckets of unit normals for the light samplers that depend on the shading normal
// (oriented_environment.h): a cube map of kFaceCells x kFaceCells cells per face, plus one bucket
// per axis for the normals that lie on it (a ground plane, an axis-aligned wall), which are common
// and can then be served by a distribution made for exactly that normal.
//
// Every normal n with of(n) == b lies within coneRadius(b) radians of center(b): the cone's
// radius is the largest angle from the cell's centre to its corners (a cube cell is bounded by
// great circles, so its farthest points from the centre are corners), with a margin for rounding.

#include <glm/glm.hpp>

namespace iblkit {

class NormalBuckets {
 public:
  static constexpr int kFaceCells = 5;  // odd, so that each axis is the centre of a cell too
  static constexpr int kCellBuckets = 6 * kFaceCells * kFaceCells;
  static constexpr int kCount = kCellBuckets + 6;
  // Normals whose two smaller components are within this fraction of the largest are on an axis.
  static constexpr float kAxisTolerance = 1e-4f;

  // The bucket of a non-zero normal (any length).
  static int of(const glm::vec3& normal);
  // Its cone: the unit centre and the radius in radians.
  static glm::vec3 center(int bucket);
  static float coneRadius(int bucket);
};

}  // namespace iblkit
