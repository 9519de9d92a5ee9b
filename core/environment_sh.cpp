#include "core/environment_sh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/latlong.h"

namespace iblkit {

SphericalHarmonics9 projectEnvironmentSh9(const EnvironmentMap& environment) {
  // Floating-point sums depend on their order. parallel_deterministic_reduce splits the rows into
  // the same tasks and joins them in the same order on every run and any number of threads (a
  // fixed grain of 4 rows), so the coefficients, the window cutoff found from them and every
  // bake stage after them are reproducible to the last bit; parallel_reduce's split follows the
  // scheduling and changed the sixth digit from run to run.
  constexpr int kRowsPerTask = 4;
  // The texels' directions are EnvironmentMap::texelDirection's, bit for bit, with each column's
  // sines taken once (latLongLongitude) instead of at every texel: half of the projection's time
  // on a 16384 x 8192 map.
  const int width = environment.width(), height = environment.height();
  std::vector<glm::vec2> longitudes(static_cast<std::size_t>(width));
  for (int x = 0; x < width; ++x)
    longitudes[static_cast<std::size_t>(x)] =
        latLongLongitude((static_cast<float>(x) + 0.5f) / static_cast<float>(width));
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<int>(0, height, kRowsPerTask), SphericalHarmonics9{},
      [&](const tbb::blocked_range<int>& rows, SphericalHarmonics9 sum) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
          const float solidAngle = environment.texelSolidAngle(y);
          const glm::vec2 latitude =
              latLongLatitude((static_cast<float>(y) + 0.5f) / static_cast<float>(height));
          for (int x = 0; x < width; ++x)
            sum.accumulate(environment.toWorldDirection(
                               latLongDirection(longitudes[static_cast<std::size_t>(x)], latitude)),
                           environment.texelRadiance(x, y), solidAngle);
        }
        return sum;
      },
      [](SphericalHarmonics9 a, const SphericalHarmonics9& b) { return a += b; });
}

float minimumIrradiance(const SphericalHarmonics9& sh, std::span<const glm::vec3> directions) {
  float minimum = INFINITY;
  for (const glm::vec3& n : directions) {
    const glm::vec3 e = sh.irradiance(n);
    minimum = std::min({minimum, e.r, e.g, e.b});
  }
  return minimum;
}

std::vector<glm::vec3> fibonacciSphere(int count) {
  // Point i at z = 1 - (2i + 1)/count (equal-area bands) and longitude i times the golden angle.
  const float goldenAngle = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  std::vector<glm::vec3> directions;
  directions.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    const float z = 1.0f - (2.0f * static_cast<float>(i) + 1.0f) / static_cast<float>(count);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = goldenAngle * static_cast<float>(i);
    directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return directions;
}

float automaticShWindowCutoff(const SphericalHarmonics9& sh) {
  const std::vector<glm::vec3> directions = fibonacciSphere(4096);
  if (minimumIrradiance(sh, directions) >= 0.0f) return 0.0f;
  // Invariant: cutoff `low` gives irradiance >= 0 (band 0 alone is pi L_0 Y_0 >= 0), `high` not.
  float low = 1.0f, high = 64.0f;
  if (minimumIrradiance(windowSh9(sh, high), directions) >= 0.0f) return high;
  for (int step = 0; step < 16; ++step) {
    const float middle = 0.5f * (low + high);
    if (minimumIrradiance(windowSh9(sh, middle), directions) >= 0.0f)
      low = middle;
    else
      high = middle;
  }
  return low;
}

namespace {

// Every texel as a light: its world direction and radiance times solid angle.
struct TexelLight {
  glm::vec3 direction;
  glm::vec3 power;
};

std::vector<TexelLight> texelLights(const EnvironmentMap& environment) {
  std::vector<TexelLight> lights;
  lights.reserve(static_cast<std::size_t>(environment.width()) *
                 static_cast<std::size_t>(environment.height()));
  for (int y = 0; y < environment.height(); ++y)
    for (int x = 0; x < environment.width(); ++x)
      lights.push_back({environment.texelDirection(x, y),
                        environment.texelRadiance(x, y) * environment.texelSolidAngle(y)});
  return lights;
}

// The irradiance at up to kNormalBlock normals at once: each light's term for every normal of the
// block, then the next light. Per normal the operations are those of the plain sum, in the same
// order (the float cosine as glm::dot forms it, (x + y) + z; its clamp; the float product; the
// double sums light by light), so the result is the same bit for bit; across the block they are
// independent, so the compiler vectorises them.
constexpr std::size_t kNormalBlock = 8;

void irradianceBlock(std::span<const TexelLight> lights, std::span<const glm::vec3> normals,
                     std::span<glm::vec3> out) {
  float nx[kNormalBlock] = {}, ny[kNormalBlock] = {}, nz[kNormalBlock] = {};
  for (std::size_t k = 0; k < normals.size(); ++k) {
    nx[k] = normals[k].x;
    ny[k] = normals[k].y;
    nz[k] = normals[k].z;
  }
  double r[kNormalBlock] = {}, g[kNormalBlock] = {}, b[kNormalBlock] = {};
  for (const TexelLight& light : lights) {
    const glm::vec3 d = light.direction, p = light.power;
    for (std::size_t k = 0; k < kNormalBlock; ++k) {
      const float cosine = std::max(0.0f, nx[k] * d.x + ny[k] * d.y + nz[k] * d.z);
      r[k] += double(p.x * cosine);
      g[k] += double(p.y * cosine);
      b[k] += double(p.z * cosine);
    }
  }
  for (std::size_t k = 0; k < normals.size(); ++k) out[k] = glm::vec3(glm::dvec3(r[k], g[k], b[k]));
}

}  // namespace

std::vector<glm::vec3> bruteForceIrradiance(const EnvironmentMap& environment,
                                            std::span<const glm::vec3> normals) {
  const std::vector<TexelLight> lights = texelLights(environment);
  std::vector<glm::vec3> irradiance(normals.size());
  const std::size_t blocks = (normals.size() + kNormalBlock - 1) / kNormalBlock;
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t block) {
    const std::size_t first = block * kNormalBlock, count = std::min(kNormalBlock, normals.size() - first);
    irradianceBlock(lights, normals.subspan(first, count), std::span(irradiance).subspan(first, count));
  });
  return irradiance;
}

CubeMap bruteForceIrradianceCube(const EnvironmentMap& environment, int size) {
  if (size < 1) throw std::invalid_argument("bruteForceIrradianceCube: size must be >= 1");
  std::vector<glm::vec3> normals;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        normals.push_back(cubeDirection(face, (glm::vec2(x, y) + 0.5f) / static_cast<float>(size)));
  const std::vector<glm::vec3> irradiance = bruteForceIrradiance(environment, normals);
  CubeMap cube{size, {}};
  std::size_t i = 0;
  for (Image& face : cube.faces) {
    face = Image(size, size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) face.at(x, y) = glm::vec4(irradiance[i++], 1.0f);
  }
  return cube;
}

}  // namespace iblkit
