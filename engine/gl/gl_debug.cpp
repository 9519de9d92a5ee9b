#include "engine/gl/gl_debug.h"

#include <epoxy/gl.h>

#include <iostream>
#include <mutex>

#include "core/error.h"

namespace iblkit {
namespace {

struct DebugState {
  std::mutex mutex;
  GlDebugMode mode = GlDebugMode::Strict;
  std::vector<std::string> messages;
};

DebugState& state() {
  static DebugState instance;
  return instance;
}

void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* /*user*/) {
  // Errors and high-severity messages only: performance and portability notes are not failures.
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  const std::string text = (length >= 0 ? std::string(message, std::size_t(length)) : std::string(message)) +
                           " (id " + std::to_string(id) + ")";
  DebugState& debug = state();
  const std::lock_guard lock(debug.mutex);
  debug.messages.push_back(text);
}

std::string glErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "GL error " + std::to_string(error);
  }
}

}  // namespace

void enableGlDebugOutput(GlDebugMode mode) {
  DebugState& debug = state();
  {
    const std::lock_guard lock(debug.mutex);
    debug.mode = mode;
    debug.messages.clear();
  }
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::vector<std::string> takeGlErrors() {
  std::vector<std::string> messages;
  {
    DebugState& debug = state();
    const std::lock_guard lock(debug.mutex);
    messages.swap(debug.messages);
  }
  // glGetError catches errors on contexts without debug output; the loop is bounded because each
  // call clears one flag (OpenGL 4.5 section 2.3.1).
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
    messages.push_back(glErrorName(error));
  return messages;
}

void checkGlErrors(const std::string& where) {
  const std::vector<std::string> messages = takeGlErrors();
  if (messages.empty()) return;
  GlDebugMode mode;
  {
    DebugState& debug = state();
    const std::lock_guard lock(debug.mutex);
    mode = debug.mode;
  }
  if (mode == GlDebugMode::Warn) {
    for (const std::string& message : messages) std::cerr << "OpenGL: " << where << ": " << message << '\n';
    return;
  }
  std::string text = "OpenGL: " + where + ": " + messages.front();
  if (messages.size() > 1) text += " (and " + std::to_string(messages.size() - 1) + " more)";
  throw Error(text);
}

}  // namespace iblkit
