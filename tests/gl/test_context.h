#pragma once
// One headless OpenGL 4.5 context per test program, made current on first use, with the strict
// debug output on. If EGL gives no context the test calling this fails with the reason (never a
// silent skip: CI has Mesa's llvmpipe).
#include "engine/gl/gl_debug.h"
#include "engine/gl/headless_context.h"

namespace iblkit::test {

inline HeadlessContext& glContext() {
  static HeadlessContext context = [] {
    HeadlessContext created = HeadlessContext::create();
    enableGlDebugOutput(GlDebugMode::Strict);
    return created;
  }();
  return context;
}

}  // namespace iblkit::test
