#pragma once
// The viewer's control panel (Dear ImGui over GLFW and OpenGL 3+): shading mode, exposure,
// environment rotation and the environment map, material overrides (base colour, roughness,
// metallic), the reference comparison, frame time, and the key help (H).
#include <string>
#include <vector>

#include "core/material.h"
#include "engine/gl/renderer.h"
#include "engine/view/environment_switcher.h"
#include "engine/view/reference_comparison.h"

struct GLFWwindow;

namespace iblkit {

// What the panel shows and edits, for one frame.
struct PanelContext {
  FrameSettings& settings;
  Renderer& renderer;
  const std::vector<Material>& originalMaterials;  // "restore" puts these back
  EnvironmentSwitcher& environments;
  ReferenceComparison* comparison;  // null without --reference
  double frameMs;                   // median frame interval
  int width, height;                // of the frame
  const std::string& contextDescription;
  bool cameraMoved;                   // the reference no longer matches the view
  const std::string& lastScreenshot;  // "saved FILE.png", or why the last one failed
  bool& autoExposure;                 // the exposure follows the frame's key (unchecked: locked)
  const std::string& openStatus;      // "baking suzi.glb in memory (3 s) ...", or why an open failed
};

// Buttons the frame loop acts on.
struct PanelActions {
  bool resetCamera = false;
  bool screenshot = false;
  std::string open;  // a file typed into the "open" field: scene, model or map (as if dropped)
};

class Panel {
 public:
  // Sets up Dear ImGui for `window` (its callbacks chain to those installed before), with no
  // imgui.ini file. Needs the window's context current.
  explicit Panel(GLFWwindow* window);
  ~Panel();
  Panel(const Panel&) = delete;
  Panel& operator=(const Panel&) = delete;

  bool visible = true;    // Tab hides the panel
  bool showHelp = false;  // H: the key help window

  // Builds this frame's widgets (newFrame ... end); render() draws them into the bound framebuffer.
  PanelActions build(PanelContext& context);
  void render();
  // True while the cursor or a text field belongs to the panel: the viewer leaves the input alone.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  // Scales the panel by panelScale of the window's content scale and sizes now, when that
  // changed (at start-up, and when the window moves to a screen of another scale); prints the
  // scale on stderr when it is not 1.
  void applyScale();

  GLFWwindow* window_ = nullptr;
  float scale_ = 1.0f;        // the scale applied
  int selectedMaterial_ = 0;  // the material the overrides edit
  char openPath_[1024] = {};  // the "open" field
};

// How much the panel is scaled up on a high-DPI screen: the monitor's content scale (GLFW's
// glfwGetWindowContentScale, 2 at 192 dpi) over what the framebuffer already has beyond the window
// (framebufferWidth / windowWidth, 2 on a Retina Mac), at least 1: a Retina Mac's 2 / 2 is 1, an
// X11 screen at 192 dpi, whose framebuffer is the window's size, 2 / 1.
float panelScale(float contentScale, int windowWidth, int framebufferWidth);

// The key and mouse help, one line each (the panel's help window and docs/viewer.md).
const std::vector<std::string>& viewerHelpLines();

}  // namespace iblkit
