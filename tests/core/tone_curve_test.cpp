#include "core/tone_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace iblkit {
namespace {

TEST(SrgbEncode, KnownValuesFromIec61966) {
  EXPECT_FLOAT_EQ(srgbEncode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbEncode(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgbEncode(0.001f), 0.01292f);        // linear segment: 12.92 x
  EXPECT_NEAR(srgbEncode(0.5f), 0.735356983f, 1e-6f);   // 1.055 * 0.5^(1/2.4) - 0.055
  EXPECT_NEAR(srgbEncode(0.18f), 0.461356129f, 1e-6f);  // middle grey
  EXPECT_FLOAT_EQ(srgbEncode(-0.5f), 0.0f);             // clamped to [0,1]
  EXPECT_FLOAT_EQ(srgbEncode(3.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgbEncode(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(SrgbEncode, ContinuousAtTheSegmentBoundary) {
  // Both pieces give 0.040450 at 0.0031308 (IEC 61966-2-1 chose the constants for this).
  const float below = std::nextafter(0.0031308f, 0.0f), above = std::nextafter(0.0031308f, 1.0f);
  EXPECT_NEAR(srgbEncode(0.0031308f), 0.04045f, 1e-6f);
  EXPECT_NEAR(srgbEncode(below), srgbEncode(above), 1e-6f);
  EXPECT_NEAR(1.055f * std::pow(above, 1.0f / 2.4f) - 0.055f, srgbEncode(above), 1e-7f);
}

TEST(SrgbDecode, KnownValuesAndInverseOfEncode) {
  EXPECT_FLOAT_EQ(srgbDecode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbDecode(1.0f), 1.0f);
  EXPECT_NEAR(srgbDecode(0.5f), 0.214041140f, 1e-6f);
  EXPECT_FLOAT_EQ(srgbDecode(0.04f), 0.04f / 12.92f);
  for (int code = 0; code <= 255; ++code) {
    const float x = code / 255.0f;
    EXPECT_NEAR(srgbEncode(srgbDecode(x)), x, 2e-6f) << "code " << code;
    EXPECT_NEAR(srgbDecode(srgbEncode(x)), x, 2e-6f) << "linear " << x;
  }
}

TEST(ToneCurve, AcesFittedKnownValues) {
  // Narkowicz 2015: x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14).
  EXPECT_FLOAT_EQ(applyToneCurve(0.0f, ToneCurve::AcesFitted), 0.0f);
  EXPECT_NEAR(applyToneCurve(1.0f, ToneCurve::AcesFitted), 2.54f / 3.16f, 1e-6f);
  EXPECT_NEAR(applyToneCurve(0.18f, ToneCurve::AcesFitted), 0.266898920f, 1e-6f);
  EXPECT_FLOAT_EQ(applyToneCurve(8.0f, ToneCurve::AcesFitted), 1.0f);  // the fit is 1.003 there: clamped
  EXPECT_FLOAT_EQ(applyToneCurve(1e30f, ToneCurve::AcesFitted), 1.0f);
}

TEST(ToneCurve, AcesFittedIsMonotoneAndApproachesOne) {
  float previous = 0.0f;
  for (float x = 0.0f; x < 20.0f; x += 0.01f) {
    const float y = applyToneCurve(x, ToneCurve::AcesFitted);
    ASSERT_GE(y, previous) << "at x = " << x;
    previous = y;
  }
  EXPECT_GT(applyToneCurve(5.0f, ToneCurve::AcesFitted), 0.98f);
  EXPECT_LT(applyToneCurve(5.0f, ToneCurve::AcesFitted), 1.0f);
}

TEST(ToneCurve, ClampAndReinhard) {
  EXPECT_FLOAT_EQ(applyToneCurve(0.3f, ToneCurve::Clamp), 0.3f);
  EXPECT_FLOAT_EQ(applyToneCurve(2.0f, ToneCurve::Clamp), 1.0f);
  EXPECT_FLOAT_EQ(applyToneCurve(1.0f, ToneCurve::Reinhard), 0.5f);
  EXPECT_FLOAT_EQ(applyToneCurve(3.0f, ToneCurve::Reinhard), 0.75f);
}

TEST(ToneCurve, NeverReturnsNaN) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::AcesFitted, ToneCurve::Reinhard}) {
    EXPECT_EQ(applyToneCurve(nan, curve), 0.0f);
    EXPECT_EQ(applyToneCurve(-inf, curve), 0.0f);
    EXPECT_EQ(applyToneCurve(-2.0f, curve), 0.0f);  // a large negative input must not map to white
    EXPECT_EQ(applyToneCurve(inf, curve), 1.0f);
  }
}

TEST(ToneMap, ExposureInStopsThenCurveThenSrgb) {
  const glm::vec3 clamped = toneMap(glm::vec3(0.25f, 0.05f, 1.0f), {2.0f, ToneCurve::Clamp});
  EXPECT_FLOAT_EQ(clamped.x, 1.0f);              // 0.25 * 4 = 1
  EXPECT_FLOAT_EQ(clamped.y, srgbEncode(0.2f));  // 0.05 * 4
  EXPECT_FLOAT_EQ(clamped.z, 1.0f);              // 4, clamped
  const glm::vec3 reinhard = toneMap(glm::vec3(2.0f), {-1.0f, ToneCurve::Reinhard});
  EXPECT_FLOAT_EQ(reinhard.x, srgbEncode(0.5f));         // 2 / 2 = 1, then 1 / (1 + 1)
  const glm::vec3 aces = toneMap(glm::vec3(0.18f), {});  // defaults: exposure 0, ACES
  EXPECT_NEAR(aces.x, srgbEncode(0.266898920f), 1e-6f);
}

}  // namespace
}  // namespace iblkit
