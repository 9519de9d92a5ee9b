#include "reference/pixel_filter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/test_scenes.h"
#include "support/chi2.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

TEST(PixelFilter, BoxIsTheUniformJitterInsideThePixel) {
  const PixelFilter box(PixelFilterKind::Box);
  EXPECT_EQ(box.sample(glm::vec2(0.25f, 0.75f)), glm::vec2(0.25f, 0.75f));
  EXPECT_EQ(box.pdf(glm::vec2(0.4f, -0.4f)), 1.0f);
  EXPECT_EQ(box.pdf(glm::vec2(0.6f, 0.0f)), 0.0f);
  EXPECT_EQ(box.radius(), 0.5f);
}

// Positions in the Gaussian's square [0.5 - r, 0.5 + r]^2 mapped onto [0,1]^2 for the harness.
TEST(PixelFilter, GaussianSamplesFollowItsPdf) {
  const PixelFilter gaussian(PixelFilterKind::Gaussian);
  const float r = gaussian.radius(), diameter = 2.0f * r;
  test::Chi2Options options;
  options.name = "gaussian_pixel_filter";
  const test::Chi2Result result = test::chi2TestSquare(
      [&](PCG32& rng) -> std::optional<glm::vec2> {
        return (gaussian.sample(rng.uniform2D()) - 0.5f + r) / diameter;
      },
      [&](const glm::vec2& p) -> double {
        return static_cast<double>(gaussian.pdf(p * diameter - r)) * diameter * diameter;
      },
      options);
  EXPECT_TRUE(result.passed) << result.message;
}

// The tabulated density is the truncated, shifted Gaussian (normalised) to within the table's
// resolution; its support is [-1.5, 1.5] pixels.
TEST(PixelFilter, GaussianPdfIsTheTruncatedGaussian) {
  const PixelFilter gaussian(PixelFilterKind::Gaussian);
  const double sigma = PixelFilter::kGaussianSigma, r = PixelFilter::kGaussianRadius;
  const auto g = [&](double x) {
    return std::exp(-x * x / (2.0 * sigma * sigma)) - std::exp(-r * r / (2.0 * sigma * sigma));
  };
  double integral = 0.0;
  constexpr int kSteps = 100000;
  for (int i = 0; i < kSteps; ++i) integral += g(-r + 2.0 * r * (i + 0.5) / kSteps) * 2.0 * r / kSteps;
  for (const double x : {0.0, 0.3, -0.6, 1.0}) {
    const double expected = g(x) * g(0.0) / (integral * integral);  // pdf(x, 0)
    EXPECT_NEAR(gaussian.pdf(glm::vec2(static_cast<float>(x), 0.0f)), expected, 0.03 * expected) << x;
  }
  EXPECT_EQ(gaussian.pdf(glm::vec2(1.6f, 0.0f)), 0.0f);
  // Samples stay inside the support around the pixel's centre (0.5, 0.5).
  for (const glm::vec2 u : {glm::vec2(0.0f), glm::vec2(0.999999f), glm::vec2(0.5f)}) {
    const glm::vec2 p = gaussian.sample(u);
    EXPECT_LE(glm::abs(p.x - 0.5f), 1.5f);
    EXPECT_LE(glm::abs(p.y - 0.5f), 1.5f);
  }
  EXPECT_NEAR(gaussian.sample(glm::vec2(0.5f)).x, 0.5f, 1e-5f);
}

// Rendered: the Gaussian spreads each pixel over its neighbours, so many more pixels of a sphere's
// silhouette are partly covered than with the box filter.
TEST(PixelFilter, GaussianRenderBlursTheSilhouette) {
  const auto partlyCovered = [](PixelFilterKind filter) {
    Scene scene = test::sphereScene(test::lambert(0.5f));
    const Camera camera = sceneCamera(scene, 1.0f);
    const RenderScene renderScene(std::move(scene));
    const EnvironmentMap environment = EnvironmentMap::constant(glm::vec3(1.0f));
    const EnvironmentSampler sampler(environment);
    const Integrator integrator(renderScene, environment, sampler,
                                test::integratorOf(IntegratorKind::Direct));
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.samplesPerPixel = 64;
    settings.filter = filter;
    const RenderResult result = render(integrator, camera, settings);
    int count = 0;
    for (const glm::vec4& m : result.mask.pixels()) count += m.r > 0.0f && m.r < 1.0f;
    return count;
  };
  const int box = partlyCovered(PixelFilterKind::Box), gaussian = partlyCovered(PixelFilterKind::Gaussian);
  EXPECT_GT(box, 20);
  EXPECT_GT(gaussian, 2 * box);
}

TEST(PixelFilter, ParsesNamesAndRefusesOthers) {
  EXPECT_EQ(parsePixelFilter("box"), PixelFilterKind::Box);
  EXPECT_EQ(parsePixelFilter("gaussian"), PixelFilterKind::Gaussian);
  EXPECT_EQ(test::errorMessage([] { parsePixelFilter("tent"); }),
            "--filter: unknown filter 'tent' (expected one of box, gaussian)");
}

}  // namespace
}  // namespace iblkit
