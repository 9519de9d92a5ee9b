#pragma once
// A small scene written into a folder for the end-to-end tests of the programs: models/ball.glb
// (a coarse UV sphere), maps/sky.exr (a 32x16 lat-long map, brighter above) and scene.json placing
// the ball on the default ground under that map, 32x24 pixels.

#include <filesystem>
#include <string>

namespace iblkit::test {

struct SmallScene {
  std::filesystem::path scene, model, map;
};

SmallScene writeSmallScene(const std::filesystem::path& root);

// Every byte of `file` ("" when it cannot be read): to check that an input is untouched.
std::string fileBytes(const std::filesystem::path& file);

}  // namespace iblkit::test
