#include "bakefile/specular_exr.h"

#include <bit>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {

namespace {

// A 1 x h strip averaged down to 1 x height (h a multiple of height).
Image shrinkColumn(const Image& column, int height) {
  const int group = column.height() / height;
  Image shrunk(1, height);
  for (int y = 0; y < height; ++y) {
    glm::vec4 sum(0.0f);
    for (int i = 0; i < group; ++i) sum += column.at(0, y * group + i);
    shrunk.at(0, y) = sum / static_cast<float>(group);
  }
  return shrunk;
}

}  // namespace

void writeSpecularCubeExr(const std::filesystem::path& path, const SpecularCube& cube) {
  const std::size_t levelCount = cube.levels.size();
  if (levelCount == 0 || cube.roughness.size() != levelCount)
    fail(path, "cannot write a specular cube without levels and one roughness per level");
  const int baseSize = cube.levels[0].size;
  if (!std::has_single_bit(static_cast<unsigned>(baseSize)) ||
      static_cast<int>(levelCount) != static_cast<int>(std::bit_width(static_cast<unsigned>(baseSize))))
    fail(path, "a specular cube of base size " + std::to_string(baseSize) +
                   " needs the full chain down to 1 x 1, got " + std::to_string(levelCount) + " levels");
  std::vector<Image> strips;
  std::string roughness;
  for (std::size_t i = 0; i < levelCount; ++i) {
    strips.push_back(cubeToExrStrip(cube.levels[i]));
    char text[32];
    std::snprintf(text, sizeof text, "%s%g", i ? " " : "", static_cast<double>(cube.roughness[i]));
    roughness += text;
  }
  // OpenEXR's ROUND_DOWN chain of a W x 6W image: ... 1 x 6, 1 x 3, 1 x 1.
  strips.push_back(shrinkColumn(strips.back(), 3));
  strips.push_back(shrinkColumn(strips.back(), 1));
  writeExrLevels(path, strips,
                 {.pixelType = PixelType::Float,
                  .envmap = EnvmapLayout::Cube,
                  .stringAttributes = {{kRoughnessPerLevelAttribute, roughness}}});
}

SpecularCube readSpecularCubeExr(const std::filesystem::path& file) {
  ExrInfo info;
  const std::vector<Image> strips = readExrLevels(file, &info);
  std::string roughnessText;
  for (const auto& [name, value] : info.stringAttributes)
    if (name == kRoughnessPerLevelAttribute) roughnessText = value;
  SpecularCube cube;
  std::istringstream values(roughnessText);
  for (float r; values >> r;) cube.roughness.push_back(r);
  if (cube.roughness.empty()) fail(file, "no " + std::string(kRoughnessPerLevelAttribute) + " attribute (not an iblkit-bake cube)");
  if (cube.roughness.size() > strips.size())
    fail(file, std::to_string(cube.roughness.size()) + " roughness levels listed but only " +
                   std::to_string(strips.size()) + " mip levels stored");
  for (std::size_t level = 0; level < cube.roughness.size(); ++level)
    cube.levels.push_back(cubeFromExrStrip(strips[level], file));
  if (cube.levels.back().size != 1) fail(file, "the specular chain does not end at 1 x 1 faces");
  return cube;
}


}  // namespace iblkit
