// Our lat-long and cube-map files follow OpenEXR's standard `envmap` layouts (ImfEnvmap.h): this
// test asks OpenEXR's own functions where each of our texels belongs and checks that is where we
// put it. Linked with OpenEXR directly (the core library keeps it private).
#include <OpenEXR/ImfEnvmap.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/cube_map.h"
#include "core/latlong.h"

namespace iblkit {
namespace {

Imath::V3f toImath(const glm::vec3& v) { return Imath::V3f(v.x, v.y, v.z); }

TEST(EnvmapOpenExr, CubeStripTexelsLandWhereOpenExrLooksForThem) {
  for (const int size : {1, 2, 7, 16}) {
    // Each texel stores its own (face, x, y), so a misplaced texel is identified exactly.
    CubeMap cube = cubeFromRadiance(size, 1, [](const glm::vec3&) { return glm::vec3(0.0f); });
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) cube.faces[f].at(x, y) = glm::vec4(float(f), float(x), float(y), 1.0f);
    const Image strip = cubeToExrStrip(cube);
    const Imath::Box2i dataWindow(Imath::V2i(0, 0), Imath::V2i(size - 1, 6 * size - 1));
    for (int f = 0; f < 6; ++f) {
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          const glm::vec2 st((x + 0.5f) / size, (y + 0.5f) / size);
          Imf::CubeMapFace face;
          Imath::V2f inFace;
          Imf::CubeMap::faceAndPixelPosition(toImath(cubeDirection(f, st)), dataWindow, face, inFace);
          const Imath::V2f p = Imf::CubeMap::pixelPosition(face, dataWindow, inFace);
          const int px = static_cast<int>(std::lround(p.x)), py = static_cast<int>(std::lround(p.y));
          ASSERT_EQ(strip.at(px, py), cube.faces[f].at(x, y))
              << "size " << size << " face " << f << " texel " << x << "," << y;
        }
      }
    }
  }
}

TEST(EnvmapOpenExr, LatLongTexelCentresMapToTheSameTexel) {
  // OpenEXR spreads longitude over pixel positions 0..W-1 (first and last column at +-pi); we use
  // texel centres (x + 0.5) / W. The axes agree, so each of our texel centres rounds to its texel.
  for (const int width : {8, 64, 512}) {
    const int height = width / 2;
    const Imath::Box2i dataWindow(Imath::V2i(0, 0), Imath::V2i(width - 1, height - 1));
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const glm::vec3 d = latLongDirection(glm::vec2((x + 0.5f) / width, (y + 0.5f) / height));
        const Imath::V2f p = Imf::LatLongMap::pixelPosition(dataWindow, toImath(d));
        ASSERT_EQ(std::lround(p.x), x) << width << " " << x << "," << y;
        ASSERT_EQ(std::lround(p.y), y) << width << " " << x << "," << y;
      }
    }
  }
}

}  // namespace
}  // namespace iblkit
