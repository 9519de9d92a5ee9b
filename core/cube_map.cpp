#include "core/cube_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/error.h"

namespace iblkit {
namespace {

// Each face as a plane of the cube [-1, 1]^3: the point with face coordinates (sc, tc) in
// [-1, 1]^2 is normal + sc * sAxis + tc * tAxis. The axes restate Table 8.19 (sc = dot(r, sAxis),
// tc = dot(r, tAxis) for a direction r with |ma| = 1).
struct FaceFrame {
  glm::vec3 normal, sAxis, tAxis;
};
constexpr std::array<FaceFrame, 6> kFaceFrames = {{
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // +X
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // -X
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // +Y
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // -Y
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // +Z
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // -Z
}};

glm::vec3 pointOnFace(int face, float sc, float tc) {
  const FaceFrame& f = kFaceFrames[face];
  return f.normal + sc * f.sAxis + tc * f.tAxis;
}

// Face coordinate in [-1, 1] of the centre of texel index i (which may be -1 or size).
float texelCentreCoordinate(int i, int size) {
  return 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(size) - 1.0f;
}

glm::vec3 texelRgb(const CubeMap& cube, int face, int x, int y) {
  return glm::vec3(cube.faces[face].at(x, y));
}

// Texel (x, y) of `face` where exactly one of x, y is one step outside [0, size): fold the
// outside texel's centre over the shared edge onto the adjacent face. The centre overshoots the
// edge by 1/size in face coordinates; the folded point lies 1/size inside the adjacent face, on
// the same line along the edge, which is exactly the centre of that face's edge texel.
glm::vec3 texelAcrossEdge(const CubeMap& cube, int face, int x, int y) {
  const int n = cube.size;
  const float sc = texelCentreCoordinate(x, n), tc = texelCentreCoordinate(y, n);
  const float overshoot = std::max(std::abs(sc), std::abs(tc)) - 1.0f;
  const FaceFrame& f = kFaceFrames[face];
  const glm::vec3 folded = (1.0f - overshoot) * f.normal + std::clamp(sc, -1.0f, 1.0f) * f.sAxis +
                           std::clamp(tc, -1.0f, 1.0f) * f.tAxis;
  const CubeCoord c = cubeCoord(folded);
  const int fx = std::min(static_cast<int>(c.st.x * static_cast<float>(n)), n - 1);
  const int fy = std::min(static_cast<int>(c.st.y * static_cast<float>(n)), n - 1);
  return texelRgb(cube, c.face, fx, fy);
}

// Texel (x, y) of `face` for x, y in [-1, size]: inside the face, across an edge, or beyond a
// corner (mean of the three texels at the cube corner).
glm::vec3 seamlessTexel(const CubeMap& cube, int face, int x, int y) {
  const int n = cube.size;
  const bool insideX = x >= 0 && x < n, insideY = y >= 0 && y < n;
  if (insideX && insideY) return texelRgb(cube, face, x, y);
  if (insideX || insideY) return texelAcrossEdge(cube, face, x, y);
  const int cx = std::clamp(x, 0, n - 1), cy = std::clamp(y, 0, n - 1);
  return (texelRgb(cube, face, cx, cy) + texelAcrossEdge(cube, face, x, cy) +
          texelAcrossEdge(cube, face, cx, y)) /
         3.0f;
}

// Position inside OpenEXR's face of our texel (x, y): OpenEXR's X and Z faces are OpenGL's
// mirrored left-right, its Y faces mirrored top-bottom. A mirror is its own inverse, so the same
// function maps strip texels back.
glm::ivec2 exrFaceTexel(int face, int x, int y, int size) {
  const bool yFace = face == kCubeFacePositiveY || face == kCubeFaceNegativeY;
  return yFace ? glm::ivec2(x, size - 1 - y) : glm::ivec2(size - 1 - x, y);
}

}  // namespace

CubeCoord cubeCoord(const glm::vec3& direction) {
  const glm::vec3 a = glm::abs(direction);
  CubeCoord c;
  float ma;
  if (a.x >= a.y && a.x >= a.z) {
    c.face = direction.x >= 0.0f ? kCubeFacePositiveX : kCubeFaceNegativeX;
    ma = a.x;
  } else if (a.y >= a.z) {
    c.face = direction.y >= 0.0f ? kCubeFacePositiveY : kCubeFaceNegativeY;
    ma = a.y;
  } else {
    c.face = direction.z >= 0.0f ? kCubeFacePositiveZ : kCubeFaceNegativeZ;
    ma = a.z;
  }
  if (ma == 0.0f) return CubeCoord{};
  const FaceFrame& f = kFaceFrames[c.face];
  // Rounding can put sc / ma a hair outside [-1, 1]; keep (s, t) in the face.
  c.st = glm::clamp(
      0.5f * (glm::vec2(glm::dot(direction, f.sAxis), glm::dot(direction, f.tAxis)) / ma + 1.0f), 0.0f, 1.0f);
  return c;
}

glm::vec3 cubeDirection(int face, const glm::vec2& st) {
  return glm::normalize(pointOnFace(face, 2.0f * st.x - 1.0f, 2.0f * st.y - 1.0f));
}

float cubeTexelSolidAngle(int size, int x, int y) {
  // Solid angle of the face rectangle from (0, 0) to (a, b).
  const auto corner = [](double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0)); };
  const double x0 = 2.0 * x / size - 1.0, x1 = 2.0 * (x + 1) / size - 1.0;
  const double y0 = 2.0 * y / size - 1.0, y1 = 2.0 * (y + 1) / size - 1.0;
  return static_cast<float>(corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0));
}

glm::vec3 sampleCubeBilinear(const CubeMap& cube, const glm::vec3& direction) {
  if (!(std::isfinite(direction.x) && std::isfinite(direction.y) && std::isfinite(direction.z)))
    return glm::vec3(std::numeric_limits<float>::quiet_NaN());
  const CubeCoord c = cubeCoord(direction);
  // Continuous texel coordinates in [-0.5, size - 0.5]: texel centres sit at integers.
  const glm::vec2 p = c.st * static_cast<float>(cube.size) - 0.5f;
  const glm::vec2 p0 = glm::floor(p), f = p - p0;
  const int x0 = static_cast<int>(p0.x), y0 = static_cast<int>(p0.y);
  const glm::vec3 top =
      glm::mix(seamlessTexel(cube, c.face, x0, y0), seamlessTexel(cube, c.face, x0 + 1, y0), f.x);
  const glm::vec3 bottom =
      glm::mix(seamlessTexel(cube, c.face, x0, y0 + 1), seamlessTexel(cube, c.face, x0 + 1, y0 + 1), f.x);
  return glm::mix(top, bottom, f.y);
}

glm::vec3 cubeTexelSeamless(const CubeMap& cube, int face, int x, int y) {
  return seamlessTexel(cube, face, x, y);
}

CubeMap cubeFromRadiance(int size, int samplesPerAxis, const RadianceFunction& radiance) {
  if (size < 1 || samplesPerAxis < 1)
    throw std::invalid_argument("cubeFromRadiance: size and samplesPerAxis must be >= 1");
  CubeMap cube;
  cube.size = size;
  const float n = static_cast<float>(samplesPerAxis);
  for (int face = 0; face < 6; ++face) {
    Image& image = cube.faces[face];
    image = Image(size, size);
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        glm::vec3 sum(0.0f);
        float weightSum = 0.0f;
        for (int j = 0; j < samplesPerAxis; ++j) {
          for (int i = 0; i < samplesPerAxis; ++i) {
            const glm::vec2 ab =
                2.0f * (glm::vec2(x, y) + (glm::vec2(i, j) + 0.5f) / n) / static_cast<float>(size) - 1.0f;
            const float weight = std::pow(1.0f + glm::dot(ab, ab), -1.5f);
            sum += weight * radiance(glm::normalize(pointOnFace(face, ab.x, ab.y)));
            weightSum += weight;
          }
        }
        image.at(x, y) = glm::vec4(sum / weightSum, 1.0f);
      }
    }
  }
  return cube;
}

CubeMap cubeFromLatLong(const Image& latLong, int size, int samplesPerAxis) {
  return cubeFromRadiance(size, samplesPerAxis, [&latLong](const glm::vec3& direction) {
    return sampleLatLongBilinear(latLong, latLongUv(direction));
  });
}

Image latLongFromCube(const CubeMap& cube, int width, int samplesPerAxis) {
  if (width < 2 || width % 2 != 0)
    throw std::invalid_argument("latLongFromCube: width must be even and >= 2");
  return latLongFromRadiance(width, width / 2, samplesPerAxis, [&cube](const glm::vec3& direction) {
    return sampleCubeBilinear(cube, direction);
  });
}

CubeMapLevels cubeMipChain(const CubeMap& base) {
  CubeMapLevels levels{base};
  while (levels.back().size > 1) {
    const CubeMap& previous = levels.back();
    CubeMap next;
    next.size = (previous.size + 1) / 2;
    for (int face = 0; face < 6; ++face) next.faces[face] = downsample2x(previous.faces[face]);
    levels.push_back(std::move(next));
  }
  return levels;
}

Image cubeToExrStrip(const CubeMap& cube) {
  const int n = cube.size;
  Image strip(n, 6 * n);
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const glm::ivec2 p = exrFaceTexel(face, x, y, n);
        strip.at(p.x, face * n + p.y) = cube.faces[face].at(x, y);
      }
    }
  }
  return strip;
}

CubeMap cubeFromExrStrip(const Image& strip, const std::filesystem::path& fileForErrors) {
  const int n = strip.width();
  if (n < 1 || strip.height() != 6 * n)
    fail(fileForErrors, "cube map strip is " + std::to_string(strip.width()) + "x" +
                            std::to_string(strip.height()) + ", expected W x 6W");
  CubeMap cube;
  cube.size = n;
  for (int face = 0; face < 6; ++face) {
    cube.faces[face] = Image(n, n);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const glm::ivec2 p = exrFaceTexel(face, x, y, n);
        cube.faces[face].at(x, y) = strip.at(p.x, face * n + p.y);
      }
    }
  }
  return cube;
}

}  // namespace iblkit
