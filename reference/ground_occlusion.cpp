#include "reference/ground_occlusion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace iblkit {

namespace {

// 5-point Gauss-Legendre rule on [-1, 1] (exact for polynomials up to degree 9).
constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                0.4786286704993665, 0.2369268850561891};

// A sphere's radius is grown by this fraction (and the smallest positive float), so that rounding in
// the cone's construction never leaves a triangle's point outside it.
constexpr float kRadiusMargin = 1e-5f;

}  // namespace

glm::vec3 upperHemisphereIrradiance(const EnvironmentMap& map) {
  const Image& image = map.image();
  const int w = image.width(), h = image.height();
  // Each row's texel mean: the bilinear lookup averaged over the longitude at a fixed latitude is
  // the interpolation, between the rows it reads, of their means (the periodic linear interpolation
  // of a row averages to its values' mean).
  std::vector<glm::dvec3> rowMean(static_cast<std::size_t>(h), glm::dvec3(0.0));
  for (int y = 0; y < h; ++y) {
    glm::dvec3 sum(0.0);
    for (int x = 0; x < w; ++x) sum += glm::dvec3(glm::vec3(image.at(x, y)));
    rowMean[static_cast<std::size_t>(y)] = sum / static_cast<double>(w);
  }
  // v in [0, 1] down the map (0 at +Y): sampleLatLongBilinear's rows floor(v h - 0.5) and the next,
  // clamped at the poles.
  const auto rowAverage = [&](double v) {
    const double py = v * h - 0.5, below = std::floor(py), fy = py - below;
    const int y0 = std::clamp(static_cast<int>(below), 0, h - 1), y1 = std::clamp(static_cast<int>(below) + 1, 0, h - 1);
    return rowMean[static_cast<std::size_t>(y0)] * (1.0 - fy) + rowMean[static_cast<std::size_t>(y1)] * fy;
  };
  // E_up = int_0^{pi/2} int_0^{2 pi} L cos(theta) sin(theta) dphi dtheta, theta = pi v:
  //      = pi^2 int_0^{1/2} R(v) sin(2 pi v) dv, R the row average above, linear between the rows'
  // centres (k + 1/2) / h: one Gauss-Legendre rule per piece, the last one cut at the horizon.
  const double pi = std::numbers::pi;
  glm::dvec3 integral(0.0);
  double a = 0.0;
  for (int k = 0; a < 0.5; ++k) {
    const double b = std::min((k + 0.5) / h, 0.5);
    if (b > a) {
      const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
      for (int i = 0; i < 5; ++i) {
        const double v = mid + half * kNodes[i];
        integral += kWeights[i] * half * std::sin(2.0 * pi * v) * rowAverage(v);
      }
    }
    a = b;
  }
  return glm::vec3(pi * pi * integral * static_cast<double>(map.intensity()));
}

std::optional<GroundOcclusion> GroundOcclusion::of(const Scene& scene, const EnvironmentMap& environment) {
  float groundLow = std::numeric_limits<float>::infinity(), groundHigh = -groundLow;
  Bounds everything;
  for (const Mesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions) {
      everything.extend(p);
      if (!mesh.isGround) continue;
      groundLow = std::min(groundLow, p.y);
      groundHigh = std::max(groundHigh, p.y);
    }
  if (!(groundLow <= groundHigh)) return std::nullopt;
  if (groundHigh - groundLow > 1e-6f * std::max(everything.radius(), 1.0f)) return std::nullopt;

  GroundOcclusion ground;
  ground.groundHeight_ = groundLow;
  ground.irradianceUp_ = upperHemisphereIrradiance(environment);
  const Bounds objects = objectBounds(scene.meshes);
  if (!objects.empty()) {
    ground.center_ = objects.center();
    float radius = 0.0f;
    for (const Mesh& mesh : scene.meshes)
      if (!mesh.isGround)
        for (const glm::vec3& p : mesh.positions) radius = std::max(radius, glm::distance(p, ground.center_));
    ground.radius_ = radius * (1.0f + kRadiusMargin) + std::numeric_limits<float>::min();
  }
  return ground;
}

GroundOcclusion::Cone GroundOcclusion::coneAt(const glm::vec3& origin) const {
  Cone cone;
  if (radius_ < 0.0f) {
    cone.empty = true;
    return cone;
  }
  const glm::vec3 toCenter = center_ - origin;
  const float distance = glm::length(toCenter);
  // Inside the sphere (or on it, to the rounding) any direction may be blocked.
  cone.cosRadius = -1.0f;
  if (!(distance > radius_ * (1.0f + kRadiusMargin))) return cone;
  cone.axis = toCenter / distance;
  const float sinRadius = radius_ / distance;
  // A little wider than the sphere's, against the rounding of the direction and the cosine.
  cone.cosRadius = std::sqrt((1.0f - sinRadius) * (1.0f + sinRadius)) - 1e-6f;
  return cone;
}

}  // namespace iblkit
