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

// A photograph wider than the context's largest texture (llvmpipe: 16384) is drawn from its
// box-filtered half (with a note), where its own upload would fail and leave the sky and the mirror
// black; a material texture or a cube face too large is refused by name before OpenGL is asked.
// Two rows keep the map small.
TEST(GpuTextures, AMapWiderThanTheLargestTextureIsDrawnHalved) {
  test::glContext();
  const GLint largest = largestTexture();
  ASSERT_GE(largest, 1024);
  EXPECT_TRUE(latLongFits(largest, 2));
  EXPECT_FALSE(latLongFits(largest + 1, 2));
  EXPECT_FALSE(latLongFits(2, largest + 1));
  const auto width = [](const GlTexture& texture) {
    GLint w = 0;
    glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_WIDTH, &w);
    return w;
  };
  EXPECT_EQ(width(uploadLatLong(Image(largest, 2, glm::vec4(1.0f)))), largest);  // at the limit, itself
  Image wide(2 * largest, 2, glm::vec4(1.0f));
  wide.at(0, 0) = wide.at(1, 1) = glm::vec4(5.0f);  // the block (5, 1; 1, 5), mean 3
  const GlTexture halved = uploadLatLong(wide);
  EXPECT_EQ(width(halved), largest);
  // Texel (0, 0) of the half is the mean of the map's 2 x 2 block there.
  float texel[4] = {};
  glGetTextureSubImage(halved.id(), 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof texel, texel);
  EXPECT_EQ(texel[0], 3.0f);
  EXPECT_EQ(test::errorMessage([&] { requireTextureFits(4, largest + 7, GL_MAX_TEXTURE_SIZE, "a texture"); }),
            "a texture is 4 x " + std::to_string(largest + 7) +
                " texels, larger than this OpenGL's largest texture (" + std::to_string(largest) +
                " on a side)");
  EXPECT_NO_THROW(checkGlErrors("after the uploads"));
}

}  // namespace
}  // namespace iblkit
