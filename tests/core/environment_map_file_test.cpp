#include "core/environment_map_file.h"

#include <gtest/gtest.h>

#include "core/cube_map.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/light_probe.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// A smooth, direction-dependent radiance, so a wrong axis or mirrored face shows up.
glm::vec3 smoothSky(const glm::vec3& d) { return glm::vec3(1.0f + d.x, 1.5f + d.y, 2.0f + 0.5f * d.z); }

TEST(EnvironmentMapFile, LatLongExrLoadsUnchanged) {
  const std::filesystem::path file = test::scratchDir() / "sky.exr";
  const Image image = latLongFromRadiance(32, 16, 2, smoothSky);
  writeExr(file, image, {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
  const EnvironmentMap map = loadEnvironmentMap(file);
  ASSERT_EQ(map.width(), 32);
  EXPECT_EQ(map.image().at(5, 7), image.at(5, 7));
}

TEST(EnvironmentMapFile, CubeExrIsConvertedToLatLong) {
  const std::filesystem::path file = test::scratchDir() / "cube.exr";
  writeExr(file, cubeToExrStrip(cubeFromRadiance(16, 2, smoothSky)),
           {.pixelType = PixelType::Float, .envmap = EnvmapLayout::Cube});
  const EnvironmentMap map = loadEnvironmentMap(file);
  ASSERT_EQ(map.width(), 64);
  ASSERT_EQ(map.height(), 32);
  for (const glm::vec3 d :
       {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, -1), glm::vec3(-0.6f, 0.0f, 0.8f)}) {
    const glm::vec3 expected = smoothSky(d), got = map.radiance(d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 0.05f) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(EnvironmentMapFile, MirrorBallProbeIsConvertedToLatLong) {
  // A mirror ball photographed along -Z: build the probe from the direction each pixel reflects.
  const int size = 64;
  Image probe(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv((x + 0.5f) / size, (y + 0.5f) / size);
      probe.at(x, y) = glm::vec4(smoothSky(mirrorBallDirection(uv)), 1.0f);
    }
  const std::filesystem::path file = test::scratchDir() / "probe.exr";
  writeExr(file, probe, {.pixelType = PixelType::Float});
  const EnvironmentMap map = loadEnvironmentMap(file, ProbeFormat::MirrorBall);
  EXPECT_EQ(map.width(), 2 * size);
  // Directions facing the camera are well resolved on a mirror ball.
  for (const glm::vec3 d : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(0, 1, 0)}) {
    const glm::vec3 expected = smoothSky(d), got = map.radiance(d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 0.05f);
  }
}

TEST(EnvironmentMapFile, BadInputNamesTheFile) {
  const std::filesystem::path file = test::scratchDir() / "wide.exr";
  writeExr(file, Image(30, 10), {});
  EXPECT_EQ(test::errorMessage([&] { loadEnvironmentMap(file); }),
            file.string() + ": lat-long map is 30x10, expected a 2:1 aspect ratio");
  EXPECT_EQ(test::errorMessage([&] { loadEnvironmentMap(file, ProbeFormat::Angular); }),
            file.string() + ": angular map is 30x10, expected a square image");
  EXPECT_EQ(
      test::errorMessage([] { parseProbeFormat("cubecross"); }),
      "--env-format: unknown environment format 'cubecross' (expected one of latlong, mirrorball, angular)");
}

}  // namespace
}  // namespace iblkit
