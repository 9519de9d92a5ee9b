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

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

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
inline glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 geometricNormal) { return offsetPoint(p, geometricNormal, 1.0f); }

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
