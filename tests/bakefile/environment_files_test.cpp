// The env/ files of a bake folder read back what was written: the specular cube chain with its
// roughness per level, the irradiance cube and the DFG table; and the readers' errors.
#include <gtest/gtest.h>

#include "bakefile/brdf_lut_exr.h"
#include "bakefile/irradiance_exr.h"
#include "bakefile/specular_exr.h"
#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// A size x size cube whose texels differ by face, position and `level`.
CubeMap patternCube(int size, int level) {
  CubeMap cube;
  cube.size = size;
  for (Image& face : cube.faces) face = Image(size, size);
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        cube.faces[face].at(x, y) = glm::vec4(float(face), float(x + 10 * y), float(level) + 0.25f, 1.0f);
  return cube;
}

TEST(SpecularExr, ReadsBackEveryLevelAndItsRoughness) {
  SpecularCube cube;
  for (int level = 0, size = 4; size >= 1; ++level, size /= 2) {
    cube.levels.push_back(patternCube(size, level));
    cube.roughness.push_back(float(level) / 2.0f);
  }
  const fs::path file = test::scratchDir() / "specular_round_trip.exr";
  writeSpecularCubeExr(file, cube);
  const SpecularCube read = readSpecularCubeExr(file);
  EXPECT_EQ(read.roughness, cube.roughness);
  ASSERT_EQ(read.levels.size(), cube.levels.size());
  for (std::size_t level = 0; level < cube.levels.size(); ++level)
    for (int face = 0; face < 6; ++face)
      EXPECT_EQ(read.levels[level].faces[face].pixels(), cube.levels[level].faces[face].pixels()) << level;
}

TEST(SpecularExr, AnExrWithoutTheRoughnessListIsNotABakedCube) {
  const fs::path file = test::scratchDir() / "plain_cube.exr";
  writeExr(file, cubeToExrStrip(patternCube(2, 0)), {.pixelType = PixelType::Float, .envmap = EnvmapLayout::Cube});
  EXPECT_EQ(test::errorMessage([&] { readSpecularCubeExr(file); }),
            file.string() + ": no iblkit:roughnessPerLevel attribute (not an iblkit-bake cube)");
}

TEST(IrradianceExr, ReadsBackTheCube) {
  const CubeMap cube = patternCube(4, 0);
  const fs::path file = test::scratchDir() / "irradiance_round_trip.exr";
  writeIrradianceCubeExr(file, cube);
  const CubeMap read = readIrradianceCubeExr(file);
  ASSERT_EQ(read.size, 4);
  for (int face = 0; face < 6; ++face) EXPECT_EQ(read.faces[face].pixels(), cube.faces[face].pixels()) << face;
}

TEST(IrradianceExr, AFileThatIsNoCubeIsRefused) {
  const fs::path file = test::scratchDir() / "flat.exr";
  writeExr(file, Image(4, 24), {.pixelType = PixelType::Float});
  EXPECT_EQ(test::errorMessage([&] { readIrradianceCubeExr(file); }),
            file.string() + ": not an OpenEXR cube map (envmap attribute)");
}

TEST(BrdfLutExr, ReadsBackTheTable) {
  Image lut(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) lut.at(x, y) = glm::vec4(0.1f * float(x), 0.2f * float(y), 0.3f, 1.0f);
  const fs::path file = test::scratchDir() / "brdf_lut_round_trip.exr";
  writeBrdfLutExr(file, lut);
  EXPECT_EQ(readBrdfLutExr(file).pixels(), lut.pixels());
}

}  // namespace
}  // namespace iblkit
