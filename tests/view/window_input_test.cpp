// The window's input queue (engine/view/window_input.h) as its GLFW callbacks fill it, without a
// window: files dropped onto the window arrive as the drop callback gives them, in order among the
// other events, and the viewer opens each as openedKind (viewer.h) says.
#include "engine/view/window_input.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE  // the key names only: GL comes from libepoxy (viewer.h)
#include <GLFW/glfw3.h>

#include "engine/view/viewer.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

TEST(WindowInput, DroppedFilesArriveInOrderAmongTheOtherEvents) {
  WindowInput input;
  input.keyPressed(GLFW_KEY_P, 0);
  const char* paths[] = {"/data/bunny.glb", "/data/maps/Sky.EXR", "/data/notes.txt"};
  input.filesDropped(3, paths);
  input.framebufferResized(200, 150);
  std::vector<fs::path> dropped;
  std::vector<OpenedKind> kinds;
  int events = 0;
  while (std::optional<InputEvent> event = input.next()) {
    if (events == 0) {
      EXPECT_TRUE(std::holds_alternative<KeyPressed>(*event));
    }
    if (const auto* file = std::get_if<FileDropped>(&*event)) {
      dropped.push_back(file->file);
      kinds.push_back(openedKind(file->file));
    }
    if (const auto* resized = std::get_if<FramebufferResized>(&*event)) {
      EXPECT_EQ(events, 4);
      EXPECT_EQ(resized->width, 200);
      EXPECT_EQ(resized->height, 150);
    }
    ++events;
  }
  EXPECT_EQ(events, 5);
  EXPECT_TRUE(input.empty());
  EXPECT_EQ(dropped, (std::vector<fs::path>{paths[0], paths[1], paths[2]}));
  EXPECT_EQ(kinds,
            (std::vector<OpenedKind>{OpenedKind::Scene, OpenedKind::Environment, OpenedKind::Unsupported}));
}

TEST(WindowInput, ADroppedFolderIsASceneAndAMissingOneIsNot) {
  const fs::path bake = test::scratchDir();
  WindowInput input;
  const std::string folder = bake.string(), missing = (bake / "gone").string();
  const char* paths[] = {folder.c_str(), missing.c_str()};
  input.filesDropped(2, paths);
  EXPECT_EQ(openedKind(std::get<FileDropped>(*input.next()).file), OpenedKind::Scene);
  EXPECT_EQ(openedKind(std::get<FileDropped>(*input.next()).file), OpenedKind::Unsupported);
  EXPECT_FALSE(input.next());
}

}  // namespace
}  // namespace iblkit
