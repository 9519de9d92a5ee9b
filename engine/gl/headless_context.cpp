#include "engine/gl/headless_context.h"

#include <epoxy/gl.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace iblkit {
namespace {

struct Attempt {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

std::string eglErrorText() {
  const EGLint error = eglGetError();
  switch (error) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    default:
      return "EGL error " + std::to_string(error);
  }
}

// Initialises `display` and creates a current OpenGL 4.5 core debug context on it, or returns why
// not (and leaves the display terminated).
std::string tryDisplay(EGLDisplay display, Attempt& attempt) {
  if (display == EGL_NO_DISPLAY) return "no display (" + eglErrorText() + ")";
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return "eglInitialize failed (" + eglErrorText() + ")";
  auto giveUp = [&](const std::string& why) {
    eglTerminate(display);
    return why;
  };
  if (!eglBindAPI(EGL_OPENGL_API)) return giveUp("no desktop OpenGL API");
  // No surface is ever made, but EGL's default surface type (window) has no configs without a
  // window system; pbuffer configs exist on every platform.
  const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount < 1)
    return giveUp("no OpenGL config");
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_CONTEXT_OPENGL_DEBUG,
                                      EGL_TRUE,
                                      EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) return giveUp("no 4.5 core context (" + eglErrorText() + ")");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    return giveUp("cannot make a surfaceless context current (" + eglErrorText() + ")");
  }
  if (epoxy_gl_version() < 45) {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    return giveUp("the context has OpenGL " + std::to_string(epoxy_gl_version()) + ", not 45");
  }
  attempt = {display, context};
  return {};
}

// Every EGL device (EGL_EXT_platform_device), in enumeration order.
std::string tryDevices(Attempt& attempt) {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
      !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device"))
    return "device: EGL_EXT_platform_device is not supported";
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count < 1) return "device: no EGL devices";
  std::vector<EGLDeviceEXT> devices(std::size_t(count), nullptr);
  eglQueryDevicesEXT(count, devices.data(), &count);
  std::string reasons;
  for (EGLint i = 0; i < count; ++i) {
    const std::string why = tryDisplay(
        eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr), attempt);
    if (why.empty()) return {};
    reasons += (reasons.empty() ? "" : "; ") + ("device " + std::to_string(i) + ": " + why);
  }
  return reasons;
}

std::string trySurfaceless(Attempt& attempt) {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    return "surfaceless: EGL_MESA_platform_surfaceless is not supported";
  const std::string why = tryDisplay(
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), attempt);
  return why.empty() ? why : "surfaceless: " + why;
}

}  // namespace

HeadlessContext HeadlessContext::create() {
  const char* forced = std::getenv("IBLKIT_EGL_PLATFORM");
  const std::string platform = forced ? forced : "";
  if (!platform.empty() && platform != "device" && platform != "surfaceless")
    fail("IBLKIT_EGL_PLATFORM", "expected device or surfaceless, got '" + platform + "'");
  Attempt attempt;
  std::string reasons, chosen;
  for (const std::string candidate : {"device", "surfaceless"}) {
    if (!platform.empty() && platform != candidate) continue;
    const std::string why = candidate == "device" ? tryDevices(attempt) : trySurfaceless(attempt);
    if (why.empty()) {
      chosen = candidate;
      break;
    }
    reasons += (reasons.empty() ? "" : "; ") + why;
  }
  if (chosen.empty()) throw Error("OpenGL 4.5 core is not available: " + reasons);
  HeadlessContext context;
  context.display_ = attempt.display;
  context.context_ = attempt.context;
  context.description_ = chosen + ": " + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", " +
                         reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return context;
}

HeadlessContext::HeadlessContext(HeadlessContext&& other) noexcept
    : display_(std::exchange(other.display_, EGL_NO_DISPLAY)),
      context_(std::exchange(other.context_, EGL_NO_CONTEXT)),
      description_(std::move(other.description_)) {}

HeadlessContext& HeadlessContext::operator=(HeadlessContext&& other) noexcept {
  std::swap(display_, other.display_);
  std::swap(context_, other.context_);
  std::swap(description_, other.description_);
  return *this;
}

HeadlessContext::~HeadlessContext() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  // The display stays initialised. EGL displays are process-wide (eglGetPlatformDisplay gives the
  // same handle again, and initialising it again is cheap), and eglTerminate unloads Mesa's
  // driver, after which LeakSanitizer reports the driver's own 112 bytes with no symbols to tell
  // them from ours (make sanitize).
}

}  // namespace iblkit
