#include "reference/normal_buckets.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace iblkit {

namespace {

// Angle margin for float rounding in the bucket's test and in the directions it is compared with.
constexpr float kMarginRadians = 1e-3f;

// Face f: the major axis f / 2 (0 x, 1 y, 2 z), positive for even f; (s, t) the two other
// components, in the order of the axes after it, over the major's magnitude, in [-1, 1].
struct FacePoint {
  int face = 0;
  float s = 0.0f, t = 0.0f;
};

FacePoint facePoint(const glm::vec3& n) {
  const glm::vec3 a = glm::abs(n);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const float major = n[axis];
  const float inverse = 1.0f / std::abs(major);
  return {2 * axis + (major < 0.0f ? 1 : 0), n[(axis + 1) % 3] * inverse, n[(axis + 2) % 3] * inverse};
}

glm::vec3 fromFace(int face, float s, float t) {
  const int axis = face / 2;
  glm::vec3 d(0.0f);
  d[axis] = face % 2 == 0 ? 1.0f : -1.0f;
  d[(axis + 1) % 3] = s;
  d[(axis + 2) % 3] = t;
  return glm::normalize(d);
}

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

int cellIndex(float s) {
  // fmin/fmax, unlike clamp, turn a NaN (a zero normal) into a bound.
  const float unit = std::fmax(0.0f, std::fmin((s + 1.0f) * 0.5f, 1.0f));
  return std::min(static_cast<int>(unit * NormalBuckets::kFaceCells), NormalBuckets::kFaceCells - 1);
}

float cellEdge(int i) { return -1.0f + 2.0f * static_cast<float>(i) / NormalBuckets::kFaceCells; }

struct Cones {
  std::array<glm::vec3, NormalBuckets::kCount> center;
  std::array<float, NormalBuckets::kCount> radius;
};

Cones makeCones() {
  Cones cones{};
  constexpr int n = NormalBuckets::kFaceCells;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int b = (face * n + j) * n + i;
        const float s0 = cellEdge(i), s1 = cellEdge(i + 1), t0 = cellEdge(j), t1 = cellEdge(j + 1);
        const glm::vec3 c = fromFace(face, 0.5f * (s0 + s1), 0.5f * (t0 + t1));
        float radius = 0.0f;
        for (const float s : {s0, s1})
          for (const float t : {t0, t1}) radius = std::max(radius, angleBetween(c, fromFace(face, s, t)));
        cones.center[static_cast<std::size_t>(b)] = c;
        cones.radius[static_cast<std::size_t>(b)] = radius + kMarginRadians;
      }
  for (int face = 0; face < 6; ++face) {
    const std::size_t b = static_cast<std::size_t>(NormalBuckets::kCellBuckets + face);
    cones.center[b] = fromFace(face, 0.0f, 0.0f);
    cones.radius[b] = std::atan(std::sqrt(2.0f) * NormalBuckets::kAxisTolerance) + kMarginRadians;
  }
  return cones;
}

const Cones& cones() {
  static const Cones table = makeCones();
  return table;
}

}  // namespace

int NormalBuckets::of(const glm::vec3& normal) {
  if (!std::isfinite(normal.x + normal.y + normal.z)) return kCellBuckets + 2;  // a bucket, never used well
  const FacePoint p = facePoint(normal);
  if (std::abs(p.s) <= kAxisTolerance && std::abs(p.t) <= kAxisTolerance) return kCellBuckets + p.face;
  return (p.face * kFaceCells + cellIndex(p.t)) * kFaceCells + cellIndex(p.s);
}

glm::vec3 NormalBuckets::center(int bucket) { return cones().center[static_cast<std::size_t>(bucket)]; }

float NormalBuckets::coneRadius(int bucket) { return cones().radius[static_cast<std::size_t>(bucket)]; }

}  // namespace iblkit
