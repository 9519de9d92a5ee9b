#pragma once
// The window viewer of iblkit-view (docs/viewer.md): a GLFW window drawing a baked scene with the
// Renderer in real time, an orbit camera, the control panel, environment switching, screenshots
// and the comparison with a path-traced reference.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bakefile/bake_folder.h"
#include "engine/gl/renderer.h"
#include "engine/view/environment_switcher.h"
#include "engine/view/load_progress.h"
#include "engine/view/reference_comparison.h"

namespace iblkit {

// Reads a bake folder, or bakes a scene or model in memory (the program decides how: iblkit-view
// binds the baker library's bakeInMemory; the viewer itself depends on no baker). `current` is
// null for the scene the viewer starts with; for a file opened from the window (dropped, or the
// panel's "open") it is the environment shown, which a bare model (.gltf, .glb) is lit by. Runs
// on a worker thread for an opened file, and then reports how far it is to `progress` (null for
// the scene the viewer starts with).
using SceneLoader = std::function<BakedScene(const std::filesystem::path& folderOrScene,
                                             const EnvironmentStages* current, LoadProgress* progress)>;

struct ViewerOptions {
  std::filesystem::path input;  // bake folder, or a scene baked in memory
  SceneLoader loadScene;                   // required: reads `input`
  EnvironmentPreparer prepareEnvironment;  // required: the stages of a map switched to
  int width = 0, height = 0;    // window size; 0: the reference's, else the scene's
  std::string mode = "full";
  float exposure = 0.0f;
  bool autoExposure = true;  // the exposure follows the frame's key (keyExposure); false: locked at `exposure`
  std::optional<float> envRotation;  // absolute about +Y (docs/conventions.md); unset: the bake's
  int samples = 1;  // MSAA
  bool noSky = false;
  unsigned textureSlots = kAllTextureSlots;       // FrameSettings::textureSlots at start
  int lightCount = -1;                            // FrameSettings::lightCount at start (< 0: all)
  bool shadows = true;                            // FrameSettings::shadows at start
  bool shadowMask = true;                         // FrameSettings::shadowMask at start
  int shadowMaskDivisor = 2;                      // FrameSettings::shadowMaskDivisor at start
  bool groundVisibility = true;                   // FrameSettings::groundVisibility at start
  float anisotropy = kDefaultTextureAnisotropy;  // Renderer's textureAnisotropy
  std::filesystem::path envDir = "assets/hdri";
  std::filesystem::path environment;  // --env: switched to at start (prefiltered on the worker)
  // --reference: the images to compare with (one reference, or a report case's reference and
  // modes), read by the program; empty: no comparison. `referenceSource` names them for the panel.
  std::vector<ComparisonImage> references;
  std::string referenceSource;
  std::string show;                   // --show: the image of `references` shown first (empty: the first)
  std::string compare = "split";      // the reference view to start with: live, split, difference, image
  int frames = 0;                     // > 0: quit after this many frames
  std::filesystem::path screenshot;   // written from the last frame, at exit, after a pending
                                      // environment switch has been uploaded
  bool panel = true;                  // false: start with the panel hidden (Tab shows it)
  std::vector<std::filesystem::path> open;  // opened after the first frame, in turn, as if dropped
};

// Loads the bake (its errors first: no window opens for a bad bake), opens the window and runs the
// frame loop until Esc, the window's close button or `frames` frames. With `frames`, prints the
// median frame time on stdout. Throws Error for bad input (a `show` that names no image: "--show:
// ..."), a missing display ("cannot open a window (...; use --headless)") or a GL error. Returns
// the exit status.
int runViewer(const ViewerOptions& options);

// What a file dropped onto the window (or typed into the panel's "open" field) is opened as.
enum class OpenedKind { Environment, Scene, Unsupported };
// .exr and .hdr: an environment map; .json, .gltf, .glb and folders: a scene (a bake folder is
// a folder); anything else is unsupported. By extension, case-insensitive; nothing is read.
OpenedKind openedKind(const std::filesystem::path& file);

}  // namespace iblkit
