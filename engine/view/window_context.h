#pragma once
// A GLFW window with an OpenGL 4.5 core context (GLX on X11), current on the creating thread.
// libepoxy resolves GL entry points for whichever context is current, so the Renderer runs
// unchanged here and under HeadlessContext (EGL).
#include <string>

struct GLFWwindow;

namespace iblkit {

class WindowContext {
 public:
  // Opens a width x height window (screen coordinates) titled `title` and makes its context
  // current; vsync off when `vsync` is false. Throws Error("cannot open a window (<why>; use
  // --headless)") when GLFW cannot start (no display) or gives no OpenGL 4.5 core context.
  static WindowContext open(int width, int height, const std::string& title, bool vsync);

  WindowContext(WindowContext&& other) noexcept;
  WindowContext& operator=(WindowContext&& other) noexcept;
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;
  // Destroys the window (GLFW stays initialised until the process exits: window_context.cpp).
  ~WindowContext();

  GLFWwindow* window() const { return window_; }
  // The framebuffer's size in pixels (may differ from the window's size on high-DPI screens).
  int framebufferWidth() const;
  int framebufferHeight() const;
  bool shouldClose() const;
  void swapBuffers() const;
  // "GLX: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6" or similar.
  const std::string& description() const { return description_; }

 private:
  WindowContext() = default;
  GLFWwindow* window_ = nullptr;
  std::string description_;
};

}  // namespace iblkit
