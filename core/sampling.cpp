#include "core/sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace iblkit {

namespace {

constexpr float kPi = glm::pi<float>();
constexpr float kTwoPi = 2.0f * glm::pi<float>();
constexpr float kPiOver4 = 0.25f * glm::pi<float>();
// The largest float below 1: inverses clamp to it so that they stay in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

float clampUnit(float u) { return std::clamp(u, 0.0f, kOneMinusEpsilon); }

// The direction with the given cos(theta) and azimuth phi = 2 pi uPhi.
glm::vec3 sphericalDirection(float cosTheta, float uPhi) {
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = kTwoPi * uPhi;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// The azimuth of w as a fraction of a turn in [0, 1) (the inverse of phi = 2 pi u).
float azimuthFraction(const glm::vec3& w) {
  float phi = std::atan2(w.y, w.x);
  if (phi < 0.0f) phi += kTwoPi;
  return clampUnit(phi / kTwoPi);
}

}  // namespace

glm::vec2 sampleUniformDiskConcentric(glm::vec2 u) {
  const glm::vec2 offset = 2.0f * u - 1.0f;
  if (offset.x == 0.0f && offset.y == 0.0f) return {0.0f, 0.0f};
  // The square's triangle wedge |x| > |y| maps to the disk sector |phi| < pi/4 (and its mirror
  // image), the other wedge to pi/4 < phi < 3 pi/4; the radius is the wedge's major coordinate.
  float r, theta;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    r = offset.x;
    theta = kPiOver4 * (offset.y / offset.x);
  } else {
    r = offset.y;
    theta = 2.0f * kPiOver4 - kPiOver4 * (offset.x / offset.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

glm::vec2 invertUniformDiskConcentricSample(glm::vec2 p) {
  const float r = std::sqrt(p.x * p.x + p.y * p.y);
  float phi = std::atan2(p.y, p.x);
  if (phi < -kPiOver4) phi += kTwoPi;  // phi in [-pi/4, 7 pi/4): the four sectors in order
  // Undo the forward map sector by sector: a negative radius there rotates the point by pi.
  glm::vec2 offset;
  if (phi < kPiOver4) {
    offset = {r, r * phi / kPiOver4};
  } else if (phi < 3.0f * kPiOver4) {
    offset = {r * (2.0f - phi / kPiOver4), r};
  } else if (phi < 5.0f * kPiOver4) {
    offset = {-r, -r * (phi - kPi) / kPiOver4};
  } else {
    offset = {-r * (2.0f - (phi - kPi) / kPiOver4), -r};
  }
  return {clampUnit(0.5f * (offset.x + 1.0f)), clampUnit(0.5f * (offset.y + 1.0f))};
}

glm::vec3 sampleUniformHemisphere(glm::vec2 u) { return sphericalDirection(u.x, u.y); }

float uniformHemispherePdf(const glm::vec3& w) { return w.z >= 0.0f ? 1.0f / kTwoPi : 0.0f; }

glm::vec2 invertUniformHemisphereSample(const glm::vec3& w) { return {clampUnit(w.z), azimuthFraction(w)}; }

glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
  const glm::vec2 d = sampleUniformDiskConcentric(u);
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

float cosineHemispherePdf(float cosTheta) { return std::max(0.0f, cosTheta) / kPi; }

glm::vec2 invertCosineHemisphereSample(const glm::vec3& w) {
  return invertUniformDiskConcentricSample({w.x, w.y});
}

glm::vec3 sampleUniformSphere(glm::vec2 u) { return sphericalDirection(1.0f - 2.0f * u.x, u.y); }

float uniformSpherePdf() { return 1.0f / (4.0f * kPi); }

glm::vec2 invertUniformSphereSample(const glm::vec3& w) {
  return {clampUnit(0.5f * (1.0f - w.z)), azimuthFraction(w)};
}

glm::vec3 sampleUniformCone(glm::vec2 u, float cosThetaMax) {
  return sphericalDirection(1.0f - u.x * (1.0f - cosThetaMax), u.y);
}

float uniformConePdf(float cosTheta, float cosThetaMax) {
  return cosTheta >= cosThetaMax ? 1.0f / (kTwoPi * (1.0f - cosThetaMax)) : 0.0f;
}

glm::vec2 invertUniformConeSample(const glm::vec3& w, float cosThetaMax) {
  return {clampUnit((1.0f - w.z) / (1.0f - cosThetaMax)), azimuthFraction(w)};
}

glm::vec3 sampleCosinePowerLobe(glm::vec2 u, float exponent) {
  return sphericalDirection(std::pow(u.x, 1.0f / (exponent + 1.0f)), u.y);
}

float cosinePowerLobePdf(float cosTheta, float exponent) {
  return cosTheta > 0.0f ? (exponent + 1.0f) / kTwoPi * std::pow(cosTheta, exponent) : 0.0f;
}

glm::vec2 invertCosinePowerLobeSample(const glm::vec3& w, float exponent) {
  return {clampUnit(std::pow(std::max(0.0f, w.z), exponent + 1.0f)), azimuthFraction(w)};
}

glm::vec2 sampleUniformTriangle(glm::vec2 u) {
  const float s = std::sqrt(u.x);
  return {1.0f - s, u.y * s};
}

glm::vec2 invertUniformTriangleSample(glm::vec2 b) {
  const float s = 1.0f - b.x;
  return {clampUnit(s * s), s > 0.0f ? clampUnit(b.y / s) : 0.0f};
}

}  // namespace iblkit
