#include "engine/view/window_input.h"

#include <GLFW/glfw3.h>

namespace iblkit {
namespace {

WindowInput& inputOf(GLFWwindow* window) {
  return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
}

}  // namespace

void WindowInput::install(GLFWwindow* window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action != GLFW_RELEASE) inputOf(w).keyPressed(key, mods);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    inputOf(w).mouseButton(button, action == GLFW_PRESS);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) { inputOf(w).cursorMoved(x, y); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double y) { inputOf(w).scrolled(y); });
  glfwSetDropCallback(
      window, [](GLFWwindow* w, int count, const char** paths) { inputOf(w).filesDropped(count, paths); });
  glfwSetFramebufferSizeCallback(
      window, [](GLFWwindow* w, int width, int height) { inputOf(w).framebufferResized(width, height); });
}

void WindowInput::filesDropped(int count, const char** paths) {
  for (int i = 0; i < count; ++i) events_.push_back(FileDropped{std::filesystem::path(paths[i])});
}

std::optional<InputEvent> WindowInput::next() {
  if (events_.empty()) return std::nullopt;
  InputEvent event = std::move(events_.front());
  events_.pop_front();
  return event;
}

}  // namespace iblkit
