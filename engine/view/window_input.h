#pragma once
// The input a window receives between frames, as events in the order they came: GLFW's callbacks
// (which run inside glfwPollEvents) append them, the viewer's frame loop takes them one by one.
// Taking them in order, rather than sampling the cursor and buttons once a frame, keeps a drag,
// a wheel turn or a key that begins and ends within one frame (scripted input, a slow frame).
// Coordinates are the window's (screen coordinates: on a high-DPI screen the framebuffer may
// have more pixels); sizes of Resized events are the framebuffer's, in pixels.
#include <deque>
#include <filesystem>
#include <optional>
#include <variant>

struct GLFWwindow;

namespace iblkit {

struct KeyPressed {
  int key = 0, mods = 0;  // GLFW_KEY_*, GLFW_MOD_* (a press or a repeat)
};
struct MouseButton {
  int button = 0;  // GLFW_MOUSE_BUTTON_*
  bool pressed = false;
};
struct CursorMoved {
  double x = 0.0, y = 0.0;  // window coordinates, from the top left
};
struct Scrolled {
  double y = 0.0;  // wheel steps, positive away from the user
};
struct FileDropped {
  std::filesystem::path file;
};
struct FramebufferResized {
  int width = 0, height = 0;  // pixels; 0 when minimised
};
using InputEvent =
    std::variant<KeyPressed, MouseButton, CursorMoved, Scrolled, FileDropped, FramebufferResized>;

class WindowInput {
 public:
  // Points `window`'s user pointer at this object and installs the key, mouse button, cursor,
  // scroll, drop and framebuffer size callbacks. Install before Dear ImGui's (panel.h), which
  // chain to them. The object must outlive the window's callbacks.
  void install(GLFWwindow* window);

  // What the callbacks call (and tests, and --open, which opens files as if dropped).
  void keyPressed(int key, int mods) { events_.push_back(KeyPressed{key, mods}); }
  void mouseButton(int button, bool pressed) { events_.push_back(MouseButton{button, pressed}); }
  void cursorMoved(double x, double y) { events_.push_back(CursorMoved{x, y}); }
  void scrolled(double y) { events_.push_back(Scrolled{y}); }
  // GLFW's drop callback: `count` UTF-8 paths, one event each, in order.
  void filesDropped(int count, const char** paths);
  void framebufferResized(int width, int height) { events_.push_back(FramebufferResized{width, height}); }

  // The oldest event not taken yet, removed; none when the queue is empty.
  std::optional<InputEvent> next();
  bool empty() const { return events_.empty(); }

 private:
  std::deque<InputEvent> events_;
};

}  // namespace iblkit
