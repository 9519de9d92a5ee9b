#include "engine/gl/gl_debug.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/test_context.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

// An invalid enum on purpose: the debug callback (or glGetError) must turn it into an Error naming
// where it was checked, and the record must be cleared afterwards.
TEST(GlDebug, AnErrorProvokedOnPurposeThrows) {
  test::glContext();
  checkGlErrors("clean start");
  glEnable(GLenum(0x1234));
  const std::string message = test::errorMessage([] { checkGlErrors("provoked"); });
  EXPECT_EQ(message.rfind("OpenGL: provoked: ", 0), 0u) << message;
  EXPECT_NE(message.find("INVALID_ENUM"), std::string::npos) << message;
  EXPECT_NO_THROW(checkGlErrors("after"));
}

TEST(GlDebug, EveryErrorIsCountedAndDrained) {
  test::glContext();
  glEnable(GLenum(0x1234));
  glBindTexture(GL_TEXTURE_2D, 987654321u);  // a name never generated: GL_INVALID_OPERATION in core
  const std::vector<std::string> messages = takeGlErrors();
  EXPECT_GE(messages.size(), 2u);
  EXPECT_TRUE(takeGlErrors().empty());
}

}  // namespace
}  // namespace iblkit
