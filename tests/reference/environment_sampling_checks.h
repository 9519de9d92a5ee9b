#pragma once
// What the tests of the environment's light samplers share (environment_sampler_test.cpp,
// median_cut_sampler_test.cpp, environment_point_lights_test.cpp): a peaked synthetic map, the
// chi-square harness set up for lat-long densities, and a quadrature over the sphere.

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <optional>
#include <string>

#include "core/environment_map.h"
#include "core/environment_map_file.h"
#include "core/image.h"
#include "core/latlong.h"
#include "support/chi2.h"
#include "support/test_paths.h"

namespace iblkit::test {

// A synthetic map with a bright soft spot and a dim gradient, turned by 35 degrees and scaled by 2:
// smooth but far from constant.
inline EnvironmentMap spotMap(int width = 64) {
  const glm::vec3 spot = glm::normalize(glm::vec3(0.3f, 0.6f, -0.7f));
  EnvironmentMap map = EnvironmentMap::fromImage(
      latLongFromRadiance(width, width / 2, 2,
                          [&](const glm::vec3& d) {
                            const float c = std::max(0.0f, glm::dot(d, spot));
                            return glm::vec3(0.2f + 0.1f * d.y) +
                                   glm::vec3(40.0f, 30.0f, 20.0f) * std::pow(c, 64.0f);
                          }),
      "spot");
  map.setRotationDegrees(35.0f);
  map.setIntensity(2.0f);
  return map;
}

// The bundled sky.exr (a sun and sky), box-downsampled to 128x64 so that the quadrature of a
// chi-square test stays quick, and turned by -60 degrees; nothing when the assets are not fetched.
inline std::optional<EnvironmentMap> downsampledSky() {
  const std::filesystem::path file = assetsDir() / "hdri" / "sky.exr";
  if (!std::filesystem::exists(file)) return std::nullopt;
  const EnvironmentMap full = loadEnvironmentMap(file);
  EnvironmentMap map = EnvironmentMap::fromImage(downsample2x(downsample2x(full.image())), file);
  map.setRotationDegrees(-60.0f);
  return map;
}

// Chi-square options for a lat-long sampler: bins in theta, so the rows of a small map are resolved
// near the poles, and a refined quadrature, the pdf being a step function on the map's texels.
// testCount: the chi-square tests of the suite (Sidak correction).
inline Chi2Options latLongChi2Options(const std::string& name, int testCount) {
  Chi2Options options;
  options.name = name;
  options.testCount = testCount;
  options.sphereBinning = SphereBinning::Theta;
  options.integrationPanels = 8;
  return options;
}

// The harness bins about +Z; the lat-long map's poles (where its density per steradian has the
// integrable 1/sin(theta) of the parameterisation) are on +-Y. The cyclic permutation (x, y, z) ->
// (z, x, y), a rotation, puts them on the harness's poles, where its sin(theta) Jacobian cancels it.
inline glm::vec3 toHarness(const glm::vec3& d) { return glm::vec3(d.z, d.x, d.y); }
inline glm::vec3 fromHarness(const glm::vec3& h) { return glm::vec3(h.y, h.z, h.x); }

// The chi-square test of a sampler with sample(u).direction and pdf(w) (EnvironmentSampler,
// MedianCutSampler).
template <class Sampler>
Chi2Result latLongChi2(const Sampler& sampler, const std::string& name, int testCount) {
  return chi2TestSphere(
      [&](PCG32& rng) { return std::optional(toHarness(sampler.sample(rng.uniform2D()).direction)); },
      [&](const glm::vec3& h) { return double(sampler.pdf(fromHarness(h))); },
      latLongChi2Options(name, testCount));
}

// Integral of f(direction) over the sphere by the midpoint rule on a thetaSteps x 2*thetaSteps
// grid in (theta, phi) about +Y, each cell weighted by its exact solid angle.
template <class Value, class Function>
Value integrateOverSphere(Function&& f, int thetaSteps) {
  Value sum(0.0);
  const double pi = glm::pi<double>(), dPhi = pi / thetaSteps;
  for (int i = 0; i < thetaSteps; ++i) {
    const double t0 = pi * i / thetaSteps, t1 = pi * (i + 1) / thetaSteps, t = 0.5 * (t0 + t1);
    for (int j = 0; j < 2 * thetaSteps; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::vec3 d(std::sin(t) * std::cos(phi), std::cos(t), std::sin(t) * std::sin(phi));
      sum += Value(f(d)) * (dPhi * (std::cos(t0) - std::cos(t1)));
    }
  }
  return sum;
}

}  // namespace iblkit::test
