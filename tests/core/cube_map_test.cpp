#include "core/cube_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/error.h"
#include "support/error_capture.h"
#include "support/expect_near.h"

namespace iblkit {
namespace {

constexpr double kPi = std::numbers::pi;

using test::expectNear;

glm::vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  return glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
}

glm::vec2 texelCentre(int x, int y, int size) { return (glm::vec2(x, y) + 0.5f) / static_cast<float>(size); }

// A cube whose every texel holds the direction of its own centre.
CubeMap directionCube(int size) {
  CubeMap cube;
  cube.size = size;
  for (int face = 0; face < 6; ++face) {
    cube.faces[face] = Image(size, size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        cube.faces[face].at(x, y) = glm::vec4(cubeDirection(face, texelCentre(x, y, size)), 1.0f);
  }
  return cube;
}

TEST(CubeMap, FaceAndCoordinatesFollowOpenGlTable) {
  // OpenGL 4.5, Table 8.19, for r = (rx, ry, rz) with components 0.25, 0.5 and a major axis of 1.
  struct Case {
    glm::vec3 direction;
    int face;
    glm::vec2 st;  // ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2)
  };
  const Case cases[] = {
      {{1.0f, 0.5f, 0.25f}, kCubeFacePositiveX, {0.375f, 0.25f}},   // sc = -rz, tc = -ry
      {{-1.0f, 0.5f, 0.25f}, kCubeFaceNegativeX, {0.625f, 0.25f}},  // sc = +rz, tc = -ry
      {{0.25f, 1.0f, 0.5f}, kCubeFacePositiveY, {0.625f, 0.75f}},   // sc = +rx, tc = +rz
      {{0.25f, -1.0f, 0.5f}, kCubeFaceNegativeY, {0.625f, 0.25f}},  // sc = +rx, tc = -rz
      {{0.25f, 0.5f, 1.0f}, kCubeFacePositiveZ, {0.625f, 0.25f}},   // sc = +rx, tc = -ry
      {{0.25f, 0.5f, -1.0f}, kCubeFaceNegativeZ, {0.375f, 0.25f}},  // sc = -rx, tc = -ry
  };
  for (const Case& c : cases) {
    for (const float length : {1.0f, 0.01f, 40.0f}) {
      const CubeCoord coord = cubeCoord(c.direction * length);
      EXPECT_EQ(coord.face, c.face);
      EXPECT_NEAR(coord.st.x, c.st.x, 1e-6f) << c.face;
      EXPECT_NEAR(coord.st.y, c.st.y, 1e-6f) << c.face;
    }
    expectNear(cubeDirection(c.face, c.st), glm::normalize(c.direction), 1e-6f);
  }
  const CubeCoord zero = cubeCoord(glm::vec3(0.0f));
  EXPECT_EQ(zero.face, kCubeFacePositiveZ);
  EXPECT_EQ(zero.st, glm::vec2(0.5f));
}

TEST(CubeMap, DirectionToFaceToDirectionRoundTrip) {
  std::mt19937 rng(3);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 d = randomDirection(rng);
    const CubeCoord c = cubeCoord(d);
    ASSERT_NEAR(glm::length(cubeDirection(c.face, c.st) - d), 0.0f, 1e-5f);
  }
  std::uniform_real_distribution<float> inside(0.001f, 0.999f);
  for (int i = 0; i < 6000; ++i) {
    const int face = i % 6;
    const glm::vec2 st(inside(rng), inside(rng));
    const CubeCoord c = cubeCoord(cubeDirection(face, st));
    ASSERT_EQ(c.face, face);
    ASSERT_NEAR(c.st.x, st.x, 1e-5f);
    ASSERT_NEAR(c.st.y, st.y, 1e-5f);
  }
}

TEST(CubeMap, TexelSolidAnglesSumToTheSphere) {
  for (const int size : {1, 2, 7, 64, 256}) {
    double sum = 0.0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) sum += 6.0 * cubeTexelSolidAngle(size, x, y);
    EXPECT_NEAR(sum / (4.0 * kPi), 1.0, 1e-4) << size;
  }
  EXPECT_NEAR(cubeTexelSolidAngle(1, 0, 0), 4.0 * kPi / 6.0, 1e-6);
  // Small texels: area (2/N)^2 times the solid angle per unit area (1 + a^2 + b^2)^(-3/2).
  const int size = 256;
  for (const int x : {0, 37, 128, 255}) {
    const glm::vec2 ab = 2.0f * texelCentre(x, 200, size) - 1.0f;
    const double approximation = std::pow(2.0 / size, 2) * std::pow(1.0 + glm::dot(ab, ab), -1.5);
    EXPECT_NEAR(cubeTexelSolidAngle(size, x, 200) / approximation, 1.0, 1e-4) << x;
  }
  // Symmetric about the face centre; the corner texel is the smallest.
  EXPECT_FLOAT_EQ(cubeTexelSolidAngle(8, 1, 2), cubeTexelSolidAngle(8, 6, 5));
  EXPECT_LT(cubeTexelSolidAngle(8, 0, 0), cubeTexelSolidAngle(8, 1, 1));
}

TEST(CubeMap, BilinearAtTexelCentreReturnsTheTexel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(0.0f, 10.0f);
  CubeMap cube;
  cube.size = 8;
  for (Image& face : cube.faces) {
    face = Image(8, 8);
    for (glm::vec4& p : face.pixels()) p = glm::vec4(value(rng), value(rng), value(rng), 1.0f);
  }
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        expectNear(sampleCubeBilinear(cube, cubeDirection(face, texelCentre(x, y, 8))),
                   glm::vec3(cube.faces[face].at(x, y)), 1e-4f);
}

TEST(CubeMap, BilinearIsSeamlessAcrossEdges) {
  const int size = 8;
  const CubeMap cube = directionCube(size);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> along(-0.95f, 0.95f);
  // Points on each of the 12 edges (two coordinates of magnitude 1), approached from both faces.
  int checked = 0;
  for (int axisA = 0; axisA < 3; ++axisA) {
    for (int axisB = axisA + 1; axisB < 3; ++axisB) {
      for (const float signA : {-1.0f, 1.0f}) {
        for (const float signB : {-1.0f, 1.0f}) {
          for (int i = 0; i < 20; ++i) {
            glm::vec3 edge(along(rng));
            edge[axisA] = signA;
            edge[axisB] = signB;
            glm::vec3 onA = edge, onB = edge;
            onB[axisA] *= 0.9999f;  // a hair onto the face of axis B
            onA[axisB] *= 0.9999f;
            ASSERT_NE(cubeCoord(onA).face, cubeCoord(onB).face);
            const glm::vec3 a = sampleCubeBilinear(cube, onA), b = sampleCubeBilinear(cube, onB);
            // Clamping at face edges would differ here by about a texel's change of direction
            // (~0.1 for size 8); seamless filtering blends the same two texels from both sides.
            ASSERT_LT(glm::length(a - b), 2e-3f) << axisA << axisB << signA << signB;
            // The blend of the two edge texels is close to the direction itself.
            ASSERT_LT(glm::length(a - glm::normalize(edge)), 0.05f);
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 12 * 20);
}

TEST(CubeMap, BilinearAtAnEdgeBlendsTheTwoEdgeTexels) {
  // On the +Z / +X edge at the height of row 3, +Z's texel (7, 3) and +X's texel (0, 3) (whose
  // s runs along -z, so its column 0 touches +Z) meet; halfway between their centres is the edge.
  CubeMap cube = directionCube(8);
  for (Image& face : cube.faces)
    for (glm::vec4& p : face.pixels()) p = glm::vec4(0.0f);
  cube.faces[kCubeFacePositiveZ].at(7, 3) = glm::vec4(4.0f);
  cube.faces[kCubeFacePositiveX].at(0, 3) = glm::vec4(2.0f);
  const float t = texelCentre(0, 3, 8).y;
  const glm::vec3 onEdge = glm::vec3(1.0f, -(2.0f * t - 1.0f), 1.0f);
  expectNear(sampleCubeBilinear(cube, onEdge), glm::vec3(3.0f), 1e-4f);
}

TEST(CubeMap, BilinearAtACornerAveragesThreeTexels) {
  CubeMap cube = directionCube(4);
  for (Image& face : cube.faces)
    for (glm::vec4& p : face.pixels()) p = glm::vec4(0.0f);
  // The three texels at the (+1, +1, +1) corner: +X (0, 0), +Y (3, 3), +Z (3, 0).
  cube.faces[kCubeFacePositiveX].at(0, 0) = glm::vec4(3.0f);
  cube.faces[kCubeFacePositiveY].at(3, 3) = glm::vec4(6.0f);
  cube.faces[kCubeFacePositiveZ].at(3, 0) = glm::vec4(9.0f);
  expectNear(sampleCubeBilinear(cube, {1, 1, 1}), glm::vec3(6.0f), 1e-4f);
  EXPECT_TRUE(std::isnan(sampleCubeBilinear(cube, {NAN, 0, 1}).x));
}

glm::vec3 smoothRadiance(const glm::vec3& d) {
  return {1.0f + 0.5f * d.x, 0.8f + 0.3f * d.y * d.z, 0.5f + 0.5f * d.z * d.z};
}

TEST(CubeMap, LatLongToCubeToLatLongRoundTrip) {
  const Image latLong = latLongFromRadiance(256, 128, 2, smoothRadiance);
  const CubeMap cube = cubeFromLatLong(latLong, 32);
  ASSERT_EQ(cube.size, 32);
  float worstCube = 0.0f;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        worstCube =
            std::max(worstCube, glm::length(glm::vec3(cube.faces[face].at(x, y)) -
                                            smoothRadiance(cubeDirection(face, texelCentre(x, y, 32)))));
  EXPECT_LT(worstCube, 1e-3f);
  const Image back = latLongFromCube(cube, 256);
  ASSERT_EQ(back.width(), 256);
  ASSERT_EQ(back.height(), 128);
  float worstLatLong = 0.0f;
  for (std::size_t i = 0; i < back.pixelCount(); ++i)
    worstLatLong = std::max(worstLatLong, glm::length(glm::vec3(back.pixels()[i] - latLong.pixels()[i])));
  EXPECT_LT(worstLatLong, 3e-3f);
  EXPECT_THROW(latLongFromCube(cube, 255), std::invalid_argument);
  EXPECT_THROW(cubeFromLatLong(latLong, 0), std::invalid_argument);
}

TEST(CubeMap, CubeFromRadianceAveragesOverSolidAngle) {
  // On the +Z face plane z = 1/|p| and dOmega = dA / |p|^3, so radiance 1/z^3 has a solid-angle
  // mean of (face area) / (face solid angle) = 4 / (4 pi / 6) over the face; a plain mean over
  // the face area would give about 2.20. (Clamped away from z = 0 for the other faces.)
  const CubeMap cube = cubeFromRadiance(
      1, 128, [](const glm::vec3& d) { return glm::vec3(std::pow(std::max(std::abs(d.z), 0.5f), -3.0f)); });
  EXPECT_NEAR(cube.faces[kCubeFacePositiveZ].at(0, 0).x, 4.0 / (4.0 * kPi / 6.0), 1e-3);
  EXPECT_EQ(cube.faces[kCubeFacePositiveZ].at(0, 0).a, 1.0f);
}

TEST(CubeMap, MipChainHalvesDownToOneTexel) {
  CubeMap base = directionCube(5);
  base.faces[kCubeFaceNegativeY].at(0, 0) = glm::vec4(8.0f);
  base.faces[kCubeFaceNegativeY].at(1, 0) = glm::vec4(4.0f);
  base.faces[kCubeFaceNegativeY].at(0, 1) = glm::vec4(0.0f);
  base.faces[kCubeFaceNegativeY].at(1, 1) = glm::vec4(0.0f);
  const CubeMapLevels levels = cubeMipChain(base);
  ASSERT_EQ(levels.size(), 4u);
  const int sizes[] = {5, 3, 2, 1};
  for (std::size_t level = 0; level < levels.size(); ++level) {
    EXPECT_EQ(levels[level].size, sizes[level]);
    for (const Image& face : levels[level].faces) {
      EXPECT_EQ(face.width(), sizes[level]);
      EXPECT_EQ(face.height(), sizes[level]);
    }
  }
  EXPECT_FLOAT_EQ(levels[1].faces[kCubeFaceNegativeY].at(0, 0).x, 3.0f);
}

// Cube corners numbered as in ImfEnvmap.h's drawing: bit 0 is +x, bit 1 is +y, bit 2 is +z.
glm::vec3 cubeCorner(int corner) {
  return {corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f};
}

TEST(CubeMap, ExrStripMatchesOpenExrLayout) {
  // ImfEnvmap.h draws each face of the W x 6W strip with the cube corners at its top-left,
  // top-right, bottom-left and bottom-right pixels: +X 3 7 1 5, -X 6 2 4 0, +Y 6 7 2 3,
  // -Y 0 1 4 5, +Z 7 6 5 4, -Z 2 3 0 1. Strip pixel (i, j) of a face then looks along the point
  // of that square at ((i + 0.5) / W, (j + 0.5) / W), which must be where the strip holds the
  // cube texel whose centre is that direction.
  const int corners[6][4] = {{3, 7, 1, 5}, {6, 2, 4, 0}, {6, 7, 2, 3},
                             {0, 1, 4, 5}, {7, 6, 5, 4}, {2, 3, 0, 1}};
  const int size = 5;
  const Image strip = cubeToExrStrip(directionCube(size));
  ASSERT_EQ(strip.width(), size);
  ASSERT_EQ(strip.height(), 6 * size);
  for (int face = 0; face < 6; ++face) {
    const glm::vec3 topLeft = cubeCorner(corners[face][0]);
    const glm::vec3 right = cubeCorner(corners[face][1]) - topLeft,
                    down = cubeCorner(corners[face][2]) - topLeft;
    ASSERT_EQ(cubeCorner(corners[face][3]), topLeft + right + down);
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        const glm::vec2 f = texelCentre(i, j, size);
        const glm::vec3 expected = glm::normalize(topLeft + f.x * right + f.y * down);
        expectNear(glm::vec3(strip.at(i, face * size + j)), expected, 1e-6f);
      }
    }
  }
}

TEST(CubeMap, ExrStripRoundTripAndErrors) {
  const CubeMap cube = directionCube(6);
  const CubeMap back = cubeFromExrStrip(cubeToExrStrip(cube), "probe.exr");
  ASSERT_EQ(back.size, 6);
  for (int face = 0; face < 6; ++face) EXPECT_EQ(back.faces[face].pixels(), cube.faces[face].pixels());
  EXPECT_EQ(test::errorMessage([] { cubeFromExrStrip(Image(4, 20), "probe.exr"); }),
            "probe.exr: cube map strip is 4x20, expected W x 6W");
  EXPECT_EQ(test::errorMessage([] { cubeFromExrStrip(Image(), "empty.exr"); }),
            "empty.exr: cube map strip is 0x0, expected W x 6W");
}

}  // namespace
}  // namespace iblkit
