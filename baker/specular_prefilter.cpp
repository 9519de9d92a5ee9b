#include "baker/specular_prefilter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/frame.h"
#include "core/image_io.h"
#include "core/low_discrepancy.h"
#include "core/microfacet.h"

namespace iblkit {

namespace {

// One GGX sample around n = +z: the reflected direction, its cosine and the source mip to read.
struct LobeSample {
  glm::vec3 direction;
  float NoL;
  float lod;
};

std::vector<LobeSample> lobeSamples(float roughness, std::uint32_t count, int sourceSize, int sourceLevels) {
  const float alpha = roughness * roughness;
  const float a2 = alpha * alpha;
  const float pi = glm::pi<float>();
  const float texelSolidAngle = 4.0f * pi / (6.0f * static_cast<float>(sourceSize * sourceSize));
  std::vector<LobeSample> samples;
  for (std::uint32_t i = 0; i < count; ++i) {
    // Inverse CDF of D(h) cos(theta_h) (Walter et al. 2007, eq. 35-36).
    const glm::vec2 u = hammersley(i, count);
    const float cosThetaH = std::sqrt((1.0f - u.x) / (1.0f + (a2 - 1.0f) * u.x));
    const float sinThetaH = std::sqrt(std::max(0.0f, 1.0f - cosThetaH * cosThetaH));
    const float phi = 2.0f * pi * u.y;
    const glm::vec3 h(sinThetaH * std::cos(phi), sinThetaH * std::sin(phi), cosThetaH);
    const glm::vec3 l = 2.0f * cosThetaH * h - glm::vec3(0.0f, 0.0f, 1.0f);
    if (l.z <= 0.0f) continue;
    // pdf(l) = D(h) cos(theta_h) / (4 V.H), and V.H = cos(theta_h) when V = N.
    const float pdf = ggxD(h, alpha) / 4.0f;
    const float sampleSolidAngle = 1.0f / (static_cast<float>(count) * pdf);
    const float lod = 0.5f * std::log2(sampleSolidAngle / texelSolidAngle) + 1.0f;
    samples.push_back({l, l.z, std::clamp(lod, 0.0f, static_cast<float>(sourceLevels - 1))});
  }
  return samples;
}

// A cube mip chain copied for fast lookups: each face of each level as RGB with a one-texel
// border holding the texels sampleCubeBilinear reads across its edges and corners
// (cubeTexelSeamless), so a bilinear tap is four plain reads with no edge cases. Lookups give
// exactly sampleCubeBilinear's values; the prefilter reads about 10^8 of them for a 2048 x 1024
// map, and the edge handling was most of their cost (docs/benchmarks.md, "Baker").
class BorderedCubeChain {
 public:
  explicit BorderedCubeChain(const CubeMapLevels& chain) {
    for (const CubeMap& cube : chain) {
      Level level;
      level.size = cube.size;
      level.stride = cube.size + 2;
      level.texels.resize(6 * std::size_t(level.stride) * std::size_t(level.stride));
      tbb::parallel_for(0, 6 * level.stride, [&](int row) {
        const int face = row / level.stride, y = row % level.stride;
        for (int x = 0; x < level.stride; ++x)
          level.texels[level.index(face, x, y)] = cubeTexelSeamless(cube, face, x - 1, y - 1);
      });
      levels_.push_back(std::move(level));
    }
  }

  int levelCount() const { return static_cast<int>(levels_.size()); }

  // Trilinear lookup: sampleCubeBilinear (same arithmetic) in the two levels around lod, blended.
  glm::vec3 trilinear(const glm::vec3& direction, float lod) const {
    const CubeCoord c = faceCoord(direction);
    const int lower = static_cast<int>(lod);
    const float t = lod - static_cast<float>(lower);
    const glm::vec3 a = bilinear(lower, c);
    if (t == 0.0f) return a;
    return glm::mix(a, bilinear(lower + 1, c), t);
  }

 private:
  // cubeCoord (cube_map.h, Table 8.19) inlined: about a fifth of the prefilter's time was the call.
  static CubeCoord faceCoord(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    CubeCoord c;
    float ma, sc, tc;
    if (a.x >= a.y && a.x >= a.z) {
      c.face = d.x >= 0.0f ? kCubeFacePositiveX : kCubeFaceNegativeX;
      ma = a.x, sc = d.x >= 0.0f ? -d.z : d.z, tc = -d.y;
    } else if (a.y >= a.z) {
      c.face = d.y >= 0.0f ? kCubeFacePositiveY : kCubeFaceNegativeY;
      ma = a.y, sc = d.x, tc = d.y >= 0.0f ? d.z : -d.z;
    } else {
      c.face = d.z >= 0.0f ? kCubeFacePositiveZ : kCubeFaceNegativeZ;
      ma = a.z, sc = d.z >= 0.0f ? d.x : -d.x, tc = -d.y;
    }
    if (ma == 0.0f) return CubeCoord{};
    c.st = glm::clamp(0.5f * (glm::vec2(sc, tc) / ma + 1.0f), 0.0f, 1.0f);
    return c;
  }

  glm::vec3 bilinear(int levelIndex, const CubeCoord& c) const {
    const Level& level = levels_[static_cast<std::size_t>(levelIndex)];
    const glm::vec2 p = c.st * static_cast<float>(level.size) - 0.5f;
    const glm::vec2 p0 = glm::floor(p), f = p - p0;
    // Texel x of the face is column x + 1 of the bordered copy; taps stay in [-1, size].
    const int x0 = std::clamp(static_cast<int>(p0.x), -1, level.size - 1) + 1,
              y0 = std::clamp(static_cast<int>(p0.y), -1, level.size - 1) + 1;
    const glm::vec3* row0 = &level.texels[level.index(c.face, x0, y0)];
    const glm::vec3* row1 = row0 + level.stride;
    const glm::vec3 top = glm::mix(row0[0], row0[1], f.x);
    const glm::vec3 bottom = glm::mix(row1[0], row1[1], f.x);
    return glm::mix(top, bottom, f.y);
  }

  struct Level {
    int size = 0, stride = 0;
    std::vector<glm::vec3> texels;  // 6 faces of stride x stride, row by row
    std::size_t index(int face, int x, int y) const {
      return (std::size_t(face) * std::size_t(stride) + std::size_t(y)) * std::size_t(stride) +
             std::size_t(x);
    }
  };
  std::vector<Level> levels_;
};

}  // namespace

std::uint32_t specularSampleCount(float roughness, std::uint32_t maxSamples) {
  const auto scaled = static_cast<std::uint32_t>(std::lround(static_cast<float>(maxSamples) * roughness));
  return std::clamp(scaled, std::min(64u, maxSamples), maxSamples);
}

namespace {

// The point (sc, tc) of `face`'s plane at distance 1 from the centre (Table 8.19 inverted).
glm::vec3 facePoint(int face, float sc, float tc) {
  switch (face) {
    case kCubeFacePositiveX:
      return {1.0f, -tc, -sc};
    case kCubeFaceNegativeX:
      return {-1.0f, -tc, sc};
    case kCubeFacePositiveY:
      return {sc, 1.0f, tc};
    case kCubeFaceNegativeY:
      return {sc, -1.0f, -tc};
    case kCubeFacePositiveZ:
      return {sc, -tc, 1.0f};
    default:
      return {-sc, -tc, -1.0f};
  }
}

// cubeFromRadiance(size, 2, radiance of `environment`) with the same arithmetic, parallel over the
// rows of the faces: for a 2048 x 1024 map the 6.3 million lat-long lookups of the source cube
// were a serial tenth of the chain's time.
CubeMap sourceCube(const EnvironmentMap& environment, int size) {
  constexpr int kSamplesPerAxis = 2;
  CubeMap cube;
  cube.size = size;
  for (Image& face : cube.faces) face = Image(size, size);
  const float n = static_cast<float>(kSamplesPerAxis);
  tbb::parallel_for(0, 6 * size, [&](int row) {
    const int face = row / size, y = row % size;
    for (int x = 0; x < size; ++x) {
      glm::vec3 sum(0.0f);
      float weightSum = 0.0f;
      for (int j = 0; j < kSamplesPerAxis; ++j) {
        for (int i = 0; i < kSamplesPerAxis; ++i) {
          const glm::vec2 ab =
              2.0f * (glm::vec2(x, y) + (glm::vec2(i, j) + 0.5f) / n) / static_cast<float>(size) - 1.0f;
          const float weight = std::pow(1.0f + glm::dot(ab, ab), -1.5f);
          sum += weight * environment.radiance(glm::normalize(facePoint(face, ab.x, ab.y)));
          weightSum += weight;
        }
      }
      cube.faces[static_cast<std::size_t>(face)].at(x, y) = glm::vec4(sum / weightSum, 1.0f);
    }
  });
  return cube;
}

}  // namespace

CubeMapLevels specularSourceChain(const EnvironmentMap& environment, int size) {
  if (size < 1) throw std::invalid_argument("specularSourceChain: size must be >= 1");
  return cubeMipChain(sourceCube(environment, size));
}

namespace {

CubeMap prefilterLevel(const BorderedCubeChain& source, int sourceSize, int size, float roughness,
                       std::uint32_t sampleCount) {
  const std::vector<LobeSample> samples =
      lobeSamples(roughness, sampleCount, sourceSize, source.levelCount());
  float weightSum = 0.0f;
  for (const LobeSample& sample : samples) weightSum += sample.NoL;
  CubeMap cube{size, {}};
  for (Image& face : cube.faces) face = Image(size, size);
  tbb::parallel_for(0, 6 * size, [&](int row) {
    const int face = row / size, y = row % size;
    for (int x = 0; x < size; ++x) {
      const Frame frame =
          Frame::fromZ(cubeDirection(face, (glm::vec2(x, y) + 0.5f) / static_cast<float>(size)));
      glm::vec3 sum(0.0f);
      for (const LobeSample& sample : samples)
        sum += sample.NoL * source.trilinear(frame.toWorld(sample.direction), sample.lod);
      cube.faces[static_cast<std::size_t>(face)].at(x, y) = glm::vec4(sum / weightSum, 1.0f);
    }
  });
  return cube;
}

}  // namespace

CubeMap prefilterSpecularLevel(const CubeMapLevels& source, int size, float roughness,
                               std::uint32_t sampleCount) {
  if (size < 1 || sampleCount < 1 || !(roughness > 0.0f && roughness <= 1.0f) || source.empty())
    throw std::invalid_argument(
        "prefilterSpecularLevel: needs size >= 1, sampleCount >= 1, roughness in (0, 1] and a source chain");
  return prefilterLevel(BorderedCubeChain(source), source[0].size, size, roughness, sampleCount);
}

int defaultSpecularBaseSize(int latLongWidth) {
  const int quarter = std::clamp(latLongWidth / 4, 1, kMaxDefaultSpecularBaseSize);
  return static_cast<int>(std::bit_floor(static_cast<unsigned>(quarter)));
}

SpecularCube prefilterSpecular(const EnvironmentMap& environment, const SpecularPrefilterOptions& options) {
  const int baseSize = options.baseSize > 0 ? options.baseSize : defaultSpecularBaseSize(environment.width());
  if (!std::has_single_bit(static_cast<unsigned>(baseSize)))
    throw std::invalid_argument("prefilterSpecular: base size " + std::to_string(baseSize) +
                                " is not a power of two");
  const int fullChain = static_cast<int>(std::bit_width(static_cast<unsigned>(baseSize)));
  const int levelCount = options.levelCount > 0 ? options.levelCount : fullChain;
  if (levelCount < 2 || levelCount > fullChain)
    throw std::invalid_argument("prefilterSpecular: " + std::to_string(levelCount) +
                                " levels, expected 2 to " + std::to_string(fullChain) + " for base size " +
                                std::to_string(baseSize));
  const CubeMapLevels source = specularSourceChain(environment, baseSize);
  const BorderedCubeChain bordered(source);
  SpecularCube cube;
  for (int i = 0; i < levelCount; ++i) {
    const float roughness = static_cast<float>(i) / static_cast<float>(levelCount - 1);
    cube.roughness.push_back(roughness);
    cube.levels.push_back(i == 0 ? source[0]
                                 : prefilterLevel(bordered, baseSize, baseSize >> i, roughness,
                                                  specularSampleCount(roughness, options.sampleCount)));
  }
  return cube;
}

}  // namespace iblkit
