#include "engine/gl/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "core/environment_sh.h"
#include "core/sh_rotation.h"
#include "core/tone_curve.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/render_target.h"
#include "gl/test_context.h"
#include "support/error_capture.h"
#include "support/bake_fixture.h"

namespace iblkit {
namespace {

constexpr int kWidth = 128, kHeight = 96;

// Where the camera ray through raster position p hits the unit sphere at the origin.
std::optional<glm::vec3> hitUnitSphere(const Camera& camera, glm::vec2 p) {
  const Ray ray = camera.primaryRay(p, kWidth, kHeight);
  const float b = glm::dot(ray.origin, ray.direction);
  const float c = glm::dot(ray.origin, ray.origin) - 1.0f;
  const float discriminant = b * b - c;
  if (discriminant < 0.0f) return std::nullopt;
  return ray.origin + (-b - std::sqrt(discriminant)) * ray.direction;
}

// Pixels whose centre and the four corners of the pixel all hit the sphere: away from the
// silhouette, where rasterised coverage and the tessellation decide.
bool interiorPixel(const Camera& camera, int x, int y) {
  for (glm::vec2 offset :
       {glm::vec2(0.5f), glm::vec2(-1.0f), glm::vec2(2.0f), glm::vec2(-1.0f, 2.0f), glm::vec2(2.0f, -1.0f)})
    if (!hitUnitSphere(camera, glm::vec2(x, y) + offset)) return false;
  return true;
}

float relativeError(const glm::vec3& value, const glm::vec3& expected) {
  return glm::length(value - expected) / glm::length(expected);
}

// The test bake's renderer, a kWidth x kHeight target and the scene's camera (the GL context first).
struct SceneFrame {
  explicit SceneFrame(const BakedScene& bake, int samples = 1)
      : renderer(bake), target(kWidth, kHeight, samples), camera(sceneCamera(bake.scene, float(kWidth) / float(kHeight))) {}
  Image render(const FrameSettings& settings) {
    renderer.render(camera, settings, target.framebuffer(), kWidth, kHeight);
    return target.readColor();
  }
  Image render(ShadingMode mode) {
    FrameSettings settings;
    settings.mode = mode;
    return render(settings);
  }
  bool context = (test::glContext(), true);
  Renderer renderer;
  RenderTarget target;
  Camera camera;
};

struct Comparison {
  int pixels = 0;
  float maxError = 0.0f, meanError = 0.0f;
};

// Renders `bake` with `settings` and compares every interior sphere pixel with expected(point,
// ray direction), and (with the sky drawn) every pixel whose whole neighbourhood misses the sphere
// with the environment along the camera ray.
template <class Expected>
Comparison compareSphere(const BakedScene& bake, const FrameSettings& settings, Expected&& expected,
                         Comparison* sky = nullptr) {
  SceneFrame frame(bake);
  const Camera& camera = frame.camera;
  const Image image = frame.render(settings);
  checkGlErrors("sphere render");
  EnvironmentMap environment = test::testSky();
  environment.setRotationDegrees(settings.envRotationDegrees);
  Comparison result;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec4 pixel = image.at(x, y);
      const glm::vec2 centre(x + 0.5f, y + 0.5f);
      if (interiorPixel(camera, x, y)) {
        EXPECT_EQ(pixel.a, 1.0f) << x << "," << y;
        const float error = relativeError(
            glm::vec3(pixel),
            expected(*hitUnitSphere(camera, centre), camera.primaryRay(centre, kWidth, kHeight).direction));
        result.maxError = std::max(result.maxError, error);
        result.meanError += error;
        ++result.pixels;
      } else if (sky && !hitUnitSphere(camera, centre + glm::vec2(2.0f)) &&
                 !hitUnitSphere(camera, centre - glm::vec2(2.0f)) &&
                 !hitUnitSphere(camera, centre + glm::vec2(2.0f, -2.0f)) &&
                 !hitUnitSphere(camera, centre + glm::vec2(-2.0f, 2.0f))) {
        EXPECT_EQ(pixel.a, 0.0f) << x << "," << y;
        const float error = relativeError(
            glm::vec3(pixel), environment.radiance(camera.primaryRay(centre, kWidth, kHeight).direction));
        sky->maxError = std::max(sky->maxError, error);
        sky->meanError += error;
        ++sky->pixels;
      }
    }
  if (result.pixels) result.meanError /= float(result.pixels);
  if (sky && sky->pixels) sky->meanError /= float(sky->pixels);
  return result;
}

Material chrome() {
  Material m;
  m.baseColor = glm::vec3(1.0f);
  m.metallic = 1.0f;
  m.roughness = 0.0f;
  return m;
}

// `mirror` against the core's bilinear lat-long lookup along reflect(d, n) of the exact sphere.
// The GPU interpolates the normals of a 48 x 96 tessellation, which tilts the reflected
// direction by a fraction of a degree; the sky is the same lookup along the camera ray.
void expectMirrorMatches(float rotationDegrees) {
  const BakedScene bake = test::makeTestBake({.sphereMaterial = chrome()});
  EnvironmentMap environment = test::testSky();
  environment.setRotationDegrees(rotationDegrees);
  FrameSettings settings;
  settings.mode = ShadingMode::Mirror;
  settings.envRotationDegrees = rotationDegrees;
  Comparison sky;
  const Comparison sphere = compareSphere(
      bake, settings,
      [&](const glm::vec3& point, const glm::vec3& direction) {
        return environment.radiance(glm::reflect(direction, glm::normalize(point)));
      },
      &sky);
  EXPECT_GT(sphere.pixels, 1500);
  EXPECT_LT(sphere.maxError, 0.02f);
  EXPECT_LT(sphere.meanError, 0.002f);
  EXPECT_GT(sky.pixels, 5000);
  EXPECT_LT(sky.maxError, 0.002f);
  std::cout << "mirror (rotation " << rotationDegrees << "): " << sphere.pixels << " sphere pixels, max "
            << sphere.maxError << " mean " << sphere.meanError << "; " << sky.pixels << " sky pixels, max "
            << sky.maxError << '\n';
}

TEST(Renderer, MirrorSphereMatchesTheCpuReflectionLookup) { expectMirrorMatches(0.0f); }

// A map with detail at the texel scale (testSky's radiance times +-60% noise per texel, 2048 x
// 1024: a photograph's foliage) seen through 128 x 96 pixels: the mirror sphere's reflection and
// the sky behind it are minified, so what a pixel should show is the map averaged over its
// footprint (the path tracer's pixel average; here 8 x 8 lookups of the core's bilinear map over
// the pixel). The engine reads the map through the footprint (sampleLatLongFootprint); the lookup
// at the pixel's centre alone, what it did before, is the yardstick.
TEST(Renderer, MirrorAndSkyAverageADetailedMapOverThePixel) {
  BakedScene bake = test::makeTestBake({.sphereMaterial = chrome()});
  bake.env.latLong = latLongFromRadiance(2048, 1024, 1, [](const glm::vec3& d) {
    const glm::vec3 smooth = test::testSkyRadiance(d);
    // A hash of the direction, in [-1, 1): texel-scale noise.
    const std::uint32_t h = std::uint32_t(std::int64_t(d.x * 1e6f) * 73856093 ^ std::int64_t(d.y * 1e6f) * 19349663 ^
                                          std::int64_t(d.z * 1e6f) * 83492791);
    return smooth * (1.0f + 0.6f * (float((h * 2654435761u) >> 8) / float(1u << 23) - 1.0f));
  });
  const EnvironmentMap environment = EnvironmentMap::fromImage(bake.env.latLong, "detail");
  SceneFrame frame(bake);
  const Camera& camera = frame.camera;
  const Image image = frame.render(ShadingMode::Mirror);
  checkGlErrors("detailed map render");
  const auto seen = [&](glm::vec2 p) {
    const glm::vec3 direction = camera.primaryRay(p, kWidth, kHeight).direction;
    const std::optional<glm::vec3> hit = hitUnitSphere(camera, p);
    return environment.radiance(hit ? glm::reflect(direction, glm::normalize(*hit)) : direction);
  };
  constexpr int kSub = 8;
  struct Errors {
    double engine = 0.0, centre = 0.0;
    int pixels = 0;
  } sphere, sky;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec2 corner(x, y);
      bool anyHit = false, allHit = true;
      for (glm::vec2 offset : {glm::vec2(-1.0f), glm::vec2(2.0f), glm::vec2(-1.0f, 2.0f), glm::vec2(2.0f, -1.0f)}) {
        anyHit = anyHit || hitUnitSphere(camera, corner + offset).has_value();
        allHit = allHit && hitUnitSphere(camera, corner + offset).has_value();
      }
      if (anyHit && !allHit) continue;  // the silhouette: coverage and tessellation decide
      glm::vec3 average(0.0f);
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) average += seen(corner + (glm::vec2(i, j) + 0.5f) / float(kSub));
      average /= float(kSub * kSub);
      Errors& errors = allHit ? sphere : sky;
      errors.engine += relativeError(glm::vec3(image.at(x, y)), average);
      errors.centre += relativeError(seen(corner + 0.5f), average);
      ++errors.pixels;
    }
  for (Errors* errors : {&sphere, &sky}) {
    errors->engine /= errors->pixels;
    errors->centre /= errors->pixels;
  }
  std::cout << "detailed map, mean relative error against the pixel average: sphere (" << sphere.pixels
            << " pixels) " << sphere.engine << ", centre lookup " << sphere.centre << "; sky (" << sky.pixels
            << " pixels) " << sky.engine << ", centre lookup " << sky.centre << '\n';
  EXPECT_GT(sphere.pixels, 1500);
  EXPECT_GT(sky.pixels, 5000);
  EXPECT_LT(sphere.engine, 0.5 * sphere.centre);
  EXPECT_LT(sky.engine, 0.5 * sky.centre);
}

TEST(Renderer, EnvironmentRotationTurnsEveryLookup) { expectMirrorMatches(90.0f); }

// E(n) of `environment` by brute force (every texel a light) at one normal.
glm::vec3 bruteForceIrradianceAt(const EnvironmentMap& environment, const glm::vec3& n) {
  return bruteForceIrradiance(environment, std::span<const glm::vec3>(&n, 1)).front();
}

Material lambertWhite() {
  Material white;
  white.baseColor = glm::vec3(0.8f, 0.7f, 0.6f);
  white.metallic = 0.0f;
  white.specular = 0.0f;
  return white;
}

// `sh` against SphericalHarmonics9::irradiance at the exact normal, for a Lambert sphere; and with
// the environment turned, against the rotated coefficients.
TEST(Renderer, DiffuseSphereMatchesTheCpuSh9Irradiance) {
  const Material white = lambertWhite();
  const BakedScene bake = test::makeTestBake({.sphereMaterial = white});
  for (float rotation : {0.0f, 60.0f}) {
    const SphericalHarmonics9 sh = rotateShAboutY(bake.env.sh9, rotation);
    FrameSettings settings;
    settings.mode = ShadingMode::Sh;
    settings.envRotationDegrees = rotation;
    const Comparison sphere = compareSphere(bake, settings, [&](const glm::vec3& point, const glm::vec3&) {
      return white.baseColor / glm::pi<float>() * sh.irradiance(glm::normalize(point));
    });
    EXPECT_GT(sphere.pixels, 1500);
    EXPECT_LT(sphere.maxError, 0.005f) << "rotation " << rotation;
    EXPECT_LT(sphere.meanError, 0.001f) << "rotation " << rotation;
    std::cout << "sh (rotation " << rotation << "): " << sphere.pixels << " pixels, max " << sphere.maxError
              << " mean " << sphere.meanError << '\n';
  }
}

// `irradiance` on a Lambert sphere against the brute-force irradiance at the exact normal: what is
// left is the cube's resolution (16 x 16 texels a face, bilinear between their centres), and with
// the environment turned, the same lookup turned.
TEST(Renderer, IrradianceModeMatchesTheCpuBruteForceIrradiance) {
  const Material white = lambertWhite();
  const BakedScene bake = test::makeTestBake({.sphereMaterial = white});
  ASSERT_EQ(bake.env.irradiance.size, 16);
  for (float rotation : {0.0f, 60.0f}) {
    EnvironmentMap environment = test::testSky();
    environment.setRotationDegrees(rotation);
    FrameSettings settings;
    settings.mode = ShadingMode::Irradiance;
    settings.envRotationDegrees = rotation;
    const Comparison sphere = compareSphere(bake, settings, [&](const glm::vec3& point, const glm::vec3&) {
      return white.baseColor / glm::pi<float>() * bruteForceIrradianceAt(environment, glm::normalize(point));
    });
    EXPECT_GT(sphere.pixels, 1500);
    EXPECT_LT(sphere.maxError, 0.01f) << "rotation " << rotation;
    EXPECT_LT(sphere.meanError, 0.001f) << "rotation " << rotation;
    std::cout << "irradiance (rotation " << rotation << "): " << sphere.pixels << " pixels, max "
              << sphere.maxError << " mean " << sphere.meanError << '\n';
  }
}

// Stages without an irradiance cube (a bake folder without env/irradiance.exr) render every mode
// but the two that need it, which refuse with one line before drawing anything.
TEST(Renderer, IrradianceModesNeedTheCube) {
  BakedScene bake = test::makeTestBake({.sphereMaterial = lambertWhite(), .rings = 4, .segments = 8});
  bake.env.irradiance = CubeMap();
  SceneFrame frame(bake);
  EXPECT_NO_THROW(frame.render(ShadingMode::Sh));
  EXPECT_EQ(test::errorMessage([&] { frame.render(ShadingMode::IrradianceAoBent); }),
            "irradiance-ao-bent mode: the environment stages have no irradiance cube (env/irradiance.exr)");
  checkGlErrors("after the refused frame");
}

// Under a peaked map (a small sun over a dim sky) `sh` and `irradiance` differ by the SH9
// truncation: on every interior pixel the GPU's difference of the two modes is the CPU's
// albedo / pi (E_brute(n) - E_SH9(n)), within the cube's resolution; and the truncation is large.
TEST(Renderer, ShAndIrradianceModesDifferByTheSh9Truncation) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.7f, 0.6f));
  const EnvironmentMap peaked =
      EnvironmentMap::fromImage(latLongFromRadiance(128, 64, 2,
                                                    [&](const glm::vec3& d) {
                                                      return glm::dot(d, sun) > std::cos(glm::radians(4.0f))
                                                                 ? glm::vec3(400.0f, 380.0f, 300.0f)
                                                                 : glm::vec3(0.2f, 0.3f, 0.5f);
                                                    }),
                                "peaked sky");
  const Material white = lambertWhite();
  BakedScene bake = test::makeTestBake({.sphereMaterial = white});
  bake.env = computeEnvironmentStages(peaked, {.shWindowCutoff = std::nullopt,
                                               .specularSamples = 16,
                                               .lutSize = 8,
                                               .lutSamples = 16,
                                               .irradianceCubeSize = 16});
  SceneFrame frame(bake);
  const Camera& camera = frame.camera;
  const Image sh = frame.render(ShadingMode::Sh), irradiance = frame.render(ShadingMode::Irradiance);
  checkGlErrors("sh and irradiance");
  const glm::vec3 brightest = white.baseColor / glm::pi<float>() * bruteForceIrradianceAt(peaked, sun);
  std::vector<glm::ivec2> interior;
  std::vector<glm::vec3> normals;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (interiorPixel(camera, x, y)) {
        interior.emplace_back(x, y);
        normals.push_back(glm::normalize(*hitUnitSphere(camera, glm::vec2(x, y) + 0.5f)));
      }
  const std::vector<glm::vec3> exact = bruteForceIrradiance(peaked, normals);
  float maxDeviation = 0.0f;
  double deviation = 0.0, truncation = 0.0, radiance = 0.0;
  for (std::size_t i = 0; i < interior.size(); ++i) {
    const int x = interior[i].x, y = interior[i].y;
    const glm::vec3 cpu = white.baseColor / glm::pi<float>() * (exact[i] - bake.env.sh9.irradiance(normals[i]));
    const glm::vec3 gpu = glm::vec3(irradiance.at(x, y)) - glm::vec3(sh.at(x, y));
    maxDeviation = std::max(maxDeviation, glm::length(gpu - cpu) / glm::length(brightest));
    deviation += glm::length(gpu - cpu);
    truncation += glm::length(cpu);
    radiance += glm::length(glm::vec3(irradiance.at(x, y)));
  }
  EXPECT_GT(interior.size(), 1500u);
  // The cube's resolution error is largest at the sun's terminator, where E has a kink.
  EXPECT_LT(maxDeviation, 0.015f);
  EXPECT_LT(deviation, 0.1 * truncation);
  EXPECT_GT(truncation / radiance, 0.03);  // the truncation matters on this map
  std::cout << "sh vs irradiance under a 4-degree sun: " << interior.size() << " pixels, mean |E - E_SH9| / E "
            << truncation / radiance << "; the GPU's difference off the CPU's by " << deviation / truncation
            << " of it on average, at most " << maxDeviation << " of the brightest pixel\n";
}

// A sun of radius 4 degrees over a sky with a hard horizon (a step SH9 rings around).
EnvironmentMap sunOverHardHorizon() {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.7f, 0.6f));
  return EnvironmentMap::fromImage(
      latLongFromRadiance(128, 64, 2,
                          [&](const glm::vec3& d) {
                            if (glm::dot(d, sun) > std::cos(glm::radians(4.0f))) return glm::vec3(750.0f, 725.0f, 650.0f);
                            return d.y > 0.0f ? glm::vec3(0.6f, 0.8f, 1.0f) : glm::vec3(0.02f, 0.02f, 0.02f);
                          }),
      "sun over a hard horizon");
}

// The viewer's environment stages of `map` with fewer samples (the tests' budget).
EnvironmentStages quickStages(const EnvironmentMap& map) {
  EnvironmentStageOptions options = kViewerEnvironmentStages;
  options.specularSamples = 16;
  options.lutSamples = 16;
  options.lutSize = 8;
  return computeEnvironmentStages(map, options);
}

// The lights modes' residual diffuse corrects SH9's truncation with the residual's own irradiance
// cube (mesh.vert, residualTruncationAt): on a lone Lambert sphere under a sun over a sky
// with a hard horizon (a step SH9 rings around), `lights` is the map's brute-force irradiance
// within the cube's resolution. Without the residual cube (a bake from before it) the residual
// is SH9's, several times further off.
TEST(Renderer, LightsModeResidualDiffuseIsTheResidualCubes) {
  const EnvironmentMap map = sunOverHardHorizon();
  const Material white = lambertWhite();
  BakedScene bake = test::makeTestBake({.sphereMaterial = white, .aoRays = 256});
  bake.env = quickStages(map);
  ASSERT_EQ(bake.env.lights.suns.size(), 1u);
  ASSERT_EQ(bake.env.residualIrradiance.size, 16);
  FrameSettings settings;
  settings.mode = ShadingMode::Lights;
  // Also with the environment turned by the viewer's extra rotation: the cube, the residual's SH9
  // and the light turn together.
  for (float rotation : {0.0f, 60.0f}) {
    settings.envRotationDegrees = rotation;
    EnvironmentMap turned = map;
    turned.setRotationDegrees(rotation);
    const auto meanError = [&](const BakedScene& stages) {
      const Comparison sphere = compareSphere(stages, settings, [&](const glm::vec3& point, const glm::vec3&) {
        return white.baseColor / glm::pi<float>() * bruteForceIrradianceAt(turned, glm::normalize(point));
      });
      EXPECT_GT(sphere.pixels, 1500);
      return double(sphere.meanError);
    };
    const double withCube = meanError(bake);
    BakedScene before = bake;
    before.env.residualIrradiance = CubeMap();
    const double withoutCube = meanError(before);
    std::cout << "lights on a lone sphere (rotation " << rotation
              << "), mean relative error against the brute-force irradiance: " << withCube
              << " with the residual cube, " << withoutCube << " with the residual SH9 alone\n";
    EXPECT_LT(withCube, 0.005) << "rotation " << rotation;
    EXPECT_GT(withoutCube, 3.0 * withCube) << "rotation " << rotation;
  }
}

// A material without a specular layer (specular and metallic 0, hasSpecularLayer false) is drawn
// by programs with the specular terms compiled out (SPECULAR_LAYER 0): the frame equals the one
// the programs with them give, which a specular factor of 1e-30 selects (its specular is 1e-30 of
// the light, its diffuse weight 1 in float), to 1e-5 at every pixel, in every mode with the BRDF
// and under a map with a sun (the lights modes draw it as a disk light).
TEST(Renderer, LambertProgramsGiveTheFrameOfTheSpecularPrograms) {
  test::glContext();
  const EnvironmentMap map = sunOverHardHorizon();
  Material clay = lambertWhite();
  clay.baseColor = glm::vec3(0.7f, 0.5f, 0.3f);
  clay.roughness = 0.3f;
  BakedScene bake = test::makeTestBake({.sphereMaterial = clay, .ground = true});
  bake.env = quickStages(map);
  ASSERT_EQ(bake.env.lights.suns.size(), 1u);
  for (Material& m : bake.scene.materials) m.specular = 0.0f, m.metallic = 0.0f;
  ASSERT_FALSE(hasSpecularLayer(bake.scene.materials[0]));
  Renderer renderer(bake);
  RenderTarget target(kWidth, kHeight, 1);
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  for (ShadingMode mode : {ShadingMode::Full, ShadingMode::FullGltfAo, ShadingMode::FullBothAo, ShadingMode::Lights,
                           ShadingMode::LightsShadowed}) {
    FrameSettings settings;
    settings.mode = mode;
    settings.drawSky = false;
    auto frame = [&](float specular) {
      for (std::size_t i = 0; i < bake.scene.materials.size(); ++i) {
        Material m = bake.scene.materials[i];
        m.specular = specular;
        renderer.setMaterial(int(i), m);
      }
      renderer.render(camera, settings, target.framebuffer(), kWidth, kHeight);
      return target.readColor();
    };
    const Image lambert = frame(0.0f), specular = frame(1e-30f);
    checkGlErrors(std::string(shadingModeName(mode)));
    double worst = 0.0, brightest = 0.0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const glm::vec3 a(lambert.at(x, y)), b(specular.at(x, y));
        brightest = std::max(brightest, double(glm::length(b)));
        worst = std::max(worst, double(glm::length(a - b) / std::max(glm::length(b), 1e-4f)));
      }
    std::cout << shadingModeName(mode) << ": largest relative difference " << worst << '\n';
    EXPECT_GT(brightest, 0.1) << shadingModeName(mode);
    EXPECT_LT(worst, 1e-5) << shadingModeName(mode);
  }
}

// A bake whose SH transfer holds interreflection (BakedScene::transferBounces > 0, iblkit-bake
// --bounces) turns the diffuse multi-bounce fit off where the transfer lights the surface: `full`
// and `full-both-ao` then give albedo / pi times the transfer's irradiance alone, darker where AO
// is below 1 (the sphere's underside over the ground) and the same where it is 1; `prt` (no fit)
// and `full-gltf-ao` (SH9 times the asset's occlusion, no transfer) are unchanged.
TEST(Renderer, AnInterreflectedTransferTurnsTheMultiBounceFitOff) {
  test::glContext();
  Material clay = lambertWhite();
  clay.baseColor = glm::vec3(0.8f);
  BakedScene plain = test::makeTestBake({.sphereMaterial = clay, .ground = true});
  BakedScene bounced = plain;
  bounced.transferBounces = 2;
  Renderer a(plain), b(bounced);
  RenderTarget target(kWidth, kHeight, 1);
  const Camera camera = sceneCamera(plain.scene, float(kWidth) / float(kHeight));
  for (ShadingMode mode : {ShadingMode::Full, ShadingMode::FullBothAo, ShadingMode::Prt, ShadingMode::FullGltfAo}) {
    FrameSettings settings;
    settings.mode = mode;
    settings.drawSky = false;
    a.render(camera, settings, target.framebuffer(), kWidth, kHeight);
    const Image withFit = target.readColor();
    b.render(camera, settings, target.framebuffer(), kWidth, kHeight);
    const Image withoutFit = target.readColor();
    checkGlErrors(std::string(shadingModeName(mode)));
    int darker = 0, brighter = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const float l0 = luminance(glm::vec3(withFit.at(x, y))), l1 = luminance(glm::vec3(withoutFit.at(x, y)));
        if (l1 < l0 * (1.0f - 1e-3f)) ++darker;
        if (l1 > l0 * (1.0f + 1e-5f) + 1e-7f) ++brighter;
      }
    std::cout << shadingModeName(mode) << ": " << darker << " pixels darker without the fit, " << brighter
              << " brighter\n";
    EXPECT_EQ(brighter, 0) << shadingModeName(mode);
    if (mode == ShadingMode::Full || mode == ShadingMode::FullBothAo)
      EXPECT_GT(darker, 200) << shadingModeName(mode);
    else
      EXPECT_EQ(darker, 0) << shadingModeName(mode);
  }
}

// Every mode gives finite radiance everywhere and light on every object pixel (the sphere touches
// the ground, so the occluded modes are nearly black at the contact point, not black); occlusion only
// darkens (sh-ao <= sh on average), and multisampling gives fractional coverage at the silhouette.
TEST(Renderer, EveryModeGivesFiniteLitPixelsOnTheObject) {
  test::glContext();
  Material plastic;
  plastic.baseColor = glm::vec3(0.7f, 0.3f, 0.2f);
  plastic.metallic = 0.0f;
  plastic.roughness = 0.4f;
  const BakedScene bake = test::makeTestBake({.sphereMaterial = plastic, .ground = true});
  Renderer renderer(bake);
  RenderTarget target(kWidth, kHeight, 4);
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  std::map<ShadingMode, double> meanLuminance;
  for (ShadingMode mode : kShadingModes) {
    FrameSettings settings;
    settings.mode = mode;
    renderer.render(camera, settings, target.framebuffer(), kWidth, kHeight);
    const Image image = target.readColor();
    checkGlErrors(std::string(shadingModeName(mode)));
    int objectPixels = 0, partialCoverage = 0;
    double sum = 0.0;
    for (const glm::vec4& p : image.pixels()) {
      ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b)) << shadingModeName(mode);
      if (p.a > 0.0f && p.a < 1.0f) ++partialCoverage;
      if (p.a < 1.0f) continue;
      ++objectPixels;
      const float luminance = 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b;
      EXPECT_GT(luminance, 0.0f) << shadingModeName(mode);
      sum += luminance;
    }
    EXPECT_GT(objectPixels, 1500) << shadingModeName(mode);
    EXPECT_GT(partialCoverage, 20) << shadingModeName(mode);
    meanLuminance[mode] = sum / objectPixels;
    EXPECT_GT(meanLuminance[mode], 0.05) << shadingModeName(mode);
  }
  EXPECT_LT(meanLuminance[ShadingMode::ShAo], meanLuminance[ShadingMode::Sh]);
  EXPECT_LT(meanLuminance[ShadingMode::Prt], meanLuminance[ShadingMode::Sh]);
}

// The GLSL tone curve (shaders/tone_curve.glsl) against toneMap (tone_curve.h): a float texture of
// 0, negatives and 1e-4 .. 1e4 presented into a float target, for every curve.
TEST(Renderer, GlslToneCurveMatchesTheCpuCurve) {
  test::glContext();
  const BakedScene bake = test::makeTestBake({.sphereMaterial = chrome(), .rings = 4, .segments = 8});
  Renderer renderer(bake);
  constexpr int kValues = 256;
  Image values(kValues, 1);
  for (int i = 0; i < kValues; ++i) {
    const float x = i == 0 ? 0.0f : std::pow(10.0f, -4.0f + 8.0f * float(i) / float(kValues - 1));
    values.at(i, 0) = glm::vec4(x, 0.5f * x, i % 7 == 0 ? -x : 2.0f * x, 1.0f);
  }
  const GlTexture texture = uploadTable(values);
  RenderTarget target(kValues, 1, 1);
  float maxError = 0.0f;
  for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::AcesFitted, ToneCurve::Reinhard}) {
    FrameSettings settings;
    settings.curve = curve;
    settings.exposure = 0.75f;
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    renderer.presentToneMapped(texture.id(), settings, 0, 0, kValues, 1);
    const Image shown = target.readColor();
    checkGlErrors("present");
    for (int i = 0; i < kValues; ++i) {
      const glm::vec3 expected = toneMap(glm::vec3(values.at(i, 0)), {.exposure = 0.75f, .curve = curve});
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(shown.at(i, 0)[c], expected[c], 1e-4f)
            << "curve " << int(curve) << " value " << values.at(i, 0)[c];
        maxError = std::max(maxError, std::abs(shown.at(i, 0)[c] - expected[c]));
      }
    }
  }
  std::cout << "tone curve: max |GLSL - C++| = " << maxError << " over " << 3 * 3 * kValues << " values\n";
}

}  // namespace
}  // namespace iblkit
