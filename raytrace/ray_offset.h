#pragma once
// Starting a secondary ray on a surface without hitting that surface again (self-intersection).
// A computed hit point is exact only to float precision and may lie just behind its triangle, so
// a ray leaving it can re-hit the same triangle at t ~ 0 (shadow acne, dark speckles in AO).
//
// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems
// (2019), chapter 6: move the origin off the surface along the geometric normal by a
// fixed number of units in the last place (ulps) of each coordinate, done as integer arithmetic on
// the float's bits. The rounding error of a computed position grows with its magnitude exactly as
// an ulp does, so one integer offset works at every scale with no scene-dependent epsilon, and
// the ray may then start at tmin = 0. Close to zero, ulps shrink far below the error (which there
// comes from the other, larger coordinates and the triangle's vertices), so coordinates smaller
// than a threshold get a small fixed float offset instead.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>

namespace iblkit {

// The chapter's constants (chosen empirically there): coordinates with magnitude
// below kOffsetOrigin move by kOffsetFloatScale * n; others by kOffsetIntScale * n ulps.
inline constexpr float kOffsetOrigin = 1.0f / 32.0f;
inline constexpr float kOffsetFloatScale = 1.0f / 65536.0f;
inline constexpr float kOffsetIntScale = 256.0f;

// p moved along the unit vector `direction` as offsetRayOrigin moves it along a normal, by
// `fraction` of its offset: kOffsetFloatScale * fraction * d for coordinates below kOffsetOrigin,
// kOffsetIntScale * fraction * d ulps for the others (truncated towards zero).
inline glm::vec3 offsetPoint(glm::vec3 p, glm::vec3 direction, float fraction) {
  glm::vec3 moved;
  for (int axis = 0; axis < 3; ++axis) {
    const float x = p[axis], n = direction[axis];
    if (std::abs(x) < kOffsetOrigin) {
      moved[axis] = x + kOffsetFloatScale * fraction * n;
      continue;
    }
    // |ulps| <= 256 fraction. A float's bits are sign and magnitude, so adding to them moves a
    // positive x up but a negative x down: flip the step for negative x. Unsigned arithmetic wraps
    // exactly like the chapter's int arithmetic, without the undefined behaviour of signed overflow.
    const auto ulps = static_cast<int32_t>(kOffsetIntScale * fraction * n);
    const uint32_t step = static_cast<uint32_t>(x < 0.0f ? -ulps : ulps);
    moved[axis] = std::bit_cast<float>(std::bit_cast<uint32_t>(x) + step);
  }
  return moved;
}

// Origin for a ray leaving the surface point p. `geometricNormal` is the unit normal of the
// triangle's plane (not an interpolated shading normal) on the side the new ray travels into:
// flip it for rays that go through the surface or leave it from the back. For best results p
// is computed from the hit's barycentrics (RayScene::surfacePoint), not as origin + t * dir.
// For a point whose error bound is known (a hit point), the overload below moves it far less.
inline glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 geometricNormal) { return offsetPoint(p, geometricNormal, 1.0f); }

// Points with a known error bound (hit points, points sampled on triangles, mesh vertices): the
// offset by that bound (after Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th
// edition, section 6.8, "Managing Rounding Error"; pbrt-v4's OffsetRayOrigin). The 256 ulps above
// are a fixed multiple of each coordinate's ulp whatever the triangle: at 3,000 units from the
// origin they are 0.06 units, at 30,000 half a unit, so a model placed far from the origin lost
// its creases' and contacts' shadows (a bunny of height 1.8 at (3000, 0, -3000) rendered lighter
// under its paw, and baked AO off by up to 0.14), and near the origin the fixed 2^-16 is a percent
// of a millimetre-sized model (its baked AO off by up to 1). Here:
//
//   a point of a triangle is computed from one corner, p0 + b1 (p1 - p0) + b2 (p2 - p0)
//     (trianglePoint): the differences of nearby floats are exact, so the point errs by the last
//     addition's rounding, half an ulp of each coordinate, and by the small terms' rounding,
//     relative to the triangle's size;
//   error_c = 2^-23 |p_c| + kPointErrorScale extent_c (surfaceErrorBound: twice the first, and
//     kPointErrorMargin times gamma(7) of the triangles' extent: Embree's own tests subtract the
//     ray's origin from the corners, exact again, and err relative to the triangles' size too);
//   p' = p + max(|n| . error, 2^-10 max_c error_c) n, with the step along n made good where
//     rounding to floats lost part of it (offsetRayOrigin below).
//
// pbrt bounds an interpolated point by gamma(7) (|b0 p0| + |b1 p1| + |b2 p2|): relative to where
// the triangle stands, which at 3,000 units moved a point of a bunny's sole, 1.8e-4 above the
// ground, below it. The floor: a point of a plane through 0 with its normal on an axis (a ground at
// y = 0) has no rounding along the normal, and an origin left on the plane is hit by it at t = 0
// (Embree counts t = tmin); 2^-10 of the largest coordinate's bound moves it off (without going
// denormal). tests/raytrace/ray_offset_test: no ray from such an origin re-hits its triangle, from
// 1e-6 to 1e3 units and up to 1e5 from the origin.
inline constexpr float kPointErrorMargin = 4.0f;
inline constexpr float kPointErrorScale = kPointErrorMargin * (7.0f * 0x1p-24f) / (1.0f - 7.0f * 0x1p-24f);

// The point of the triangle (p0, p1, p2) with barycentric coordinates (1 - b1 - b2, b1, b2), from
// its first corner (see above).
inline glm::vec3 trianglePoint(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, float b1, float b2) {
  return p0 + (b1 * (p1 - p0) + b2 * (p2 - p0));
}

// The error bound of a point p computed by trianglePoint, or of a mesh vertex, whose triangles
// span `extent` per axis (see above).
inline glm::vec3 surfaceErrorBound(glm::vec3 p, glm::vec3 extent) {
  return 0x1p-23f * glm::abs(p) + kPointErrorScale * extent;
}

// The extent per axis of the triangle (p0, p1, p2).
inline glm::vec3 triangleExtent(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
  return glm::max(p0, glm::max(p1, p2)) - glm::min(p0, glm::min(p1, p2));
}

// The distance offsetRayOrigin below moves a point with error bound `error` along the unit normal n.
inline float offsetDistance(glm::vec3 error, glm::vec3 n) {
  return std::max(glm::dot(glm::abs(n), error), std::max({error.x, error.y, error.z}) * 0x1p-10f);
}

// p (with per-coordinate error bound `error`) moved off its surface along the unit
// `geometricNormal` (the side the ray leaves into) by offsetDistance: p + distance n, and, where
// rounding that to floats lost part of the step along n (a coordinate's share smaller than its
// ulp), the coordinate along n's largest component moved further until the step along n is the
// distance again. pbrt rounds every coordinate one float away instead: far from the origin, where
// an ulp exceeds the step, that moved points sideways by a whole ulp along n's small components,
// under the neighbouring triangle of a crease (tests/baker/vertex_visibility_test).
inline glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 error, glm::vec3 geometricNormal) {
  const float distance = offsetDistance(error, geometricNormal);
  glm::vec3 moved = p + distance * geometricNormal;
  const glm::vec3 magnitude = glm::abs(geometricNormal);
  const int axis = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : (magnitude.y >= magnitude.z ? 1 : 2);
  const double n = geometricNormal[axis];
  if (n == 0.0) return moved;  // not a unit normal
  const float away = n > 0.0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
  for (int pass = 0; pass < 2; ++pass) {
    const double along = glm::dot(glm::dvec3(moved) - glm::dvec3(p), glm::dvec3(geometricNormal));
    if (along >= double(distance)) break;
    // The deficit along n, taken up by the dominant coordinate, then one float more.
    moved[axis] = std::nextafter(static_cast<float>(double(moved[axis]) + (double(distance) - along) / n), away);
  }
  return moved;
}

// Relative size of rayEpsilon: 2^-16 of the largest coordinate is 128 of its ulps (an ulp of a
// float of magnitude m is about m * 2^-23), the order of the origin offset above.
inline constexpr float kRayEpsilonRelative = 0x1p-16f;

// Distance tolerance for the far end of a ray between two surface points, which offsetRayOrigin
// does not cover: a shadow or visibility ray from p to a point q on another surface uses
// direction q - p and tmax = 1 - rayEpsilon / |q - p|, so q's own surface (on which the rounded
// q may lie just behind) does not count as an occluder. Also the tmin for an origin that is not a
// surface point with a known normal. Not a substitute for offsetRayOrigin at a ray's start: a
// grazing ray from a point just behind its surface stays behind it for far longer than any
// epsilon (as Wächter and Binder point out). `magnitude` is the largest absolute coordinate in
// the scene (RayScene::rayEpsilon passes it); the result is a distance.
inline float rayEpsilon(float magnitude) { return kRayEpsilonRelative * magnitude; }

}  // namespace iblkit
