#include "engine/view/window_context.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <utility>

#include "core/error.h"

namespace iblkit {
namespace {

// GLFW reports errors through a callback; the last one explains a failed glfwInit or window.
std::string lastGlfwError;

void recordGlfwError(int, const char* description) { lastGlfwError = description ? description : "unknown"; }

[[noreturn]] void failToOpen(const std::string& why) {
  throw Error("cannot open a window (" + why + "; use --headless)");
}

}  // namespace

WindowContext WindowContext::open(int width, int height, const std::string& title, bool vsync) {
  lastGlfwError.clear();
  glfwSetErrorCallback(recordGlfwError);
  if (!glfwInit()) failToOpen("no display: " + lastGlfwError);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // present.frag writes display values itself
  WindowContext context;
  context.window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!context.window_) {
    const std::string why = lastGlfwError;
    glfwTerminate();
    failToOpen("no OpenGL 4.5 core context: " + why);
  }
  glfwMakeContextCurrent(context.window_);
  glfwSwapInterval(vsync ? 1 : 0);
  context.description_ = std::string("GLX: ") + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) +
                         ", " + reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return context;
}

WindowContext::WindowContext(WindowContext&& other) noexcept
    : window_(std::exchange(other.window_, nullptr)), description_(std::move(other.description_)) {}

WindowContext& WindowContext::operator=(WindowContext&& other) noexcept {
  std::swap(window_, other.window_);
  std::swap(description_, other.description_);
  return *this;
}

// GLFW itself stays initialised until the process exits: glfwTerminate closes the X display, and
// Mesa then unloads its driver, leaving 112 bytes of it unreachable, which LeakSanitizer reports
// (make sanitize). A later open() reuses the initialised library.
WindowContext::~WindowContext() {
  if (window_) glfwDestroyWindow(window_);
}

int WindowContext::framebufferWidth() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return width;
}

int WindowContext::framebufferHeight() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return height;
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_); }

void WindowContext::swapBuffers() const { glfwSwapBuffers(window_); }

}  // namespace iblkit
