// The viewer's difference view on the GPU (engine/view/difference_heat_map.h) against the scorer's
// heat map on the CPU (heatMapImage of relativeSquaredErrorMap, score/): the same colours, within
// one 8-bit display step.
#include "engine/view/difference_heat_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/image.h"
#include "core/tone_curve.h"
#include "engine/gl/render_target.h"
#include "gl/test_context.h"
#include "score/heat_map.h"
#include "score/image_metrics.h"

namespace iblkit {
namespace {

// A reference and a test image whose relMSE terms sweep 0 to well above maxValue: bright and
// near-black references (the epsilon matters), over- and under-estimates, per-channel differences.
void makePair(int width, int height, Image& reference, Image& test) {
  reference = Image(width, height);
  test = Image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float s = float(x + width * y) / float(width * height - 1);
      const glm::vec3 r(0.02f + 2.0f * s, 0.5f * (1.0f - s), y % 2 == 0 ? 0.0f : 4.0f * s);
      const glm::vec3 scale(1.0f + 1.5f * std::sin(7.0f * s), 1.0f - 0.8f * s, 1.0f + s);
      reference.at(x, y) = glm::vec4(r, 1.0f);
      test.at(x, y) = glm::vec4(r * scale + glm::vec3(0.0f, 0.0f, 0.05f * float(x % 3)), 1.0f);
    }
}

void expectGpuHeatMapMatchesTheScorer(float maxValue) {
  test::glContext();
  constexpr int kWidth = 16, kHeight = 8;
  Image reference, test;
  makePair(kWidth, kHeight, reference, test);
  const Image cpu = heatMapImage(relativeSquaredErrorMap(reference, test), kWidth, kHeight, maxValue);

  // Uploaded with image row 0 at GL row 0; readColor turns the rows back over, so the output's row
  // y is the images' row kHeight - 1 - y.
  const GlTexture live = uploadTable(test), ref = uploadTable(reference);
  const DifferenceHeatMap heatMap;
  RenderTarget target(kWidth, kHeight, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  heatMap.draw(live.id(), ref.id(), maxValue, kWidth, kHeight, 0, 0, kWidth, kHeight);
  const Image gpu = target.readColor();
  checkGlErrors("difference heat map");

  int distinct = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec4 expected = cpu.at(x, kHeight - 1 - y);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(gpu.at(x, y)[c], srgbEncode(expected[c]), 1.0f / 255.0f)
            << "pixel " << x << ", " << kHeight - 1 - y << " channel " << c;
      distinct += glm::vec3(expected) != glm::vec3(cpu.at(0, 0));
    }
  EXPECT_GT(distinct, kWidth * kHeight / 2);  // the pair spans the colour map, not one colour
}

TEST(DifferenceHeatMap, EqualsTheScorersHeatMap) { expectGpuHeatMapMatchesTheScorer(1.0f); }

TEST(DifferenceHeatMap, ScalesLikeTheScorersMaxValue) { expectGpuHeatMapMatchesTheScorer(0.05f); }

}  // namespace
}  // namespace iblkit
