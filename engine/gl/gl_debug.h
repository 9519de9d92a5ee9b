#pragma once
// OpenGL's debug output (KHR_debug, core in 4.3) routed to us: in the strict mode every GL error
// and every high-severity message is recorded, and checkGlErrors() turns them into an exception,
// so a test or a frame fails instead of drawing garbage.
#include <string>
#include <vector>

namespace iblkit {

enum class GlDebugMode {
  Strict,  // errors and high-severity messages are recorded; checkGlErrors() throws
  Warn,    // they are recorded the same way; checkGlErrors() prints them to stderr instead
};

// Installs the callback on the current context (which needs GL_CONTEXT_FLAG_DEBUG_BIT for all
// messages; HeadlessContext asks for one) with synchronous output, so the message comes from the
// call that caused it. Clears what was recorded.
void enableGlDebugOutput(GlDebugMode mode);

// The messages recorded since the last call, cleared; also drains glGetError.
std::vector<std::string> takeGlErrors();

// Strict mode: throws Error("OpenGL: <where>: <first message> (and N more)") when messages were
// recorded since the last call (or glGetError reports one). Warn mode: prints them, one a line.
void checkGlErrors(const std::string& where);

}  // namespace iblkit
