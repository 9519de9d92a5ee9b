#pragma once
// An OpenGL 4.5 core context without a window, through EGL (for iblkit-view --headless and the
// tests). Platforms, tried in this order unless IBLKIT_EGL_PLATFORM=device|surfaceless forces one:
//   device       EGL_EXT_platform_device: every EGL device in turn (GPUs, and Mesa's software one)
//   surfaceless  EGL_MESA_platform_surfaceless (Mesa: llvmpipe when no GPU is there)
// The context renders into framebuffer objects only (no default framebuffer: EGL_NO_SURFACE).
#include <epoxy/egl.h>

#include <string>

namespace iblkit {

class HeadlessContext {
 public:
  // Creates the context and makes it current on the calling thread. Throws Error("OpenGL 4.5 core
  // is not available: <why>") when no platform gives one (the reason of each attempt, joined).
  static HeadlessContext create();

  HeadlessContext(HeadlessContext&& other) noexcept;
  HeadlessContext& operator=(HeadlessContext&& other) noexcept;
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;
  ~HeadlessContext();

  // "surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6" or similar.
  const std::string& description() const { return description_; }

 private:
  HeadlessContext() = default;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string description_;
};

}  // namespace iblkit
