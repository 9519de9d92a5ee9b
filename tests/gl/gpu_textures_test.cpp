#include "engine/gl/gpu_textures.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <string>

#include "gl/test_context.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

GLint largestTexture() {
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  return largest;
}

// A photograph wider than the context's largest texture (llvmpipe: 16384) would leave the sky and
// the mirror black; it is refused by name before OpenGL is asked. One row keeps it small.
TEST(GpuTextures, AMapWiderThanTheLargestTextureIsRefusedByName) {
  test::glContext();
  const GLint largest = largestTexture();
  ASSERT_GE(largest, 1024);
  EXPECT_NE(uploadLatLong(Image(largest, 1, glm::vec4(1.0f))).id(), 0u);  // at the limit it loads
  EXPECT_EQ(test::errorMessage([&] { uploadLatLong(Image(largest + 1, 1, glm::vec4(1.0f))); }),
            "the environment map is " + std::to_string(largest + 1) +
                " x 1 texels, larger than this OpenGL's largest texture (" + std::to_string(largest) +
                " on a side)");
  EXPECT_EQ(test::errorMessage([&] { requireTextureFits(4, largest + 7, GL_MAX_TEXTURE_SIZE, "a texture"); }),
            "a texture is 4 x " + std::to_string(largest + 7) +
                " texels, larger than this OpenGL's largest texture (" + std::to_string(largest) +
                " on a side)");
  EXPECT_NO_THROW(checkGlErrors("after the refused uploads"));
}

}  // namespace
}  // namespace iblkit
