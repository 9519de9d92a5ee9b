// The engine's shadowed disk lights (issue 15, "Shadows"; docs/engine.md "Shadows") against the
// reference: a sphere above a ground plane under a map that is one disk sun of angular radius 3
// degrees plus a dim uniform sky, written as EXR here. iblkit-trace renders the map's texels as
// they are; the engine draws the sun as a disk light with the same direction, radius and radiance,
// and the sky as the residual. Along the image row through the shadow's centre, the shadow's edges
// (the 50% crossing between the lit ground and the umbra) and their penumbra widths (10% to 90%)
// must agree within 2 pixels at 320 x 180. The shadowed ground outside the shadow must equal the
// unshadowed lights mode (no acne), also under a sun 10 degrees above the horizon, and a sphere
// resting on the ground casts its shadow from the contact (no peter-panning).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "baker/bake_in_memory.h"
#include "baker/environment_stages.h"
#include "bakefile/vertex_attributes.h"
#include "core/disk_irradiance.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/procedural_mesh.h"
#include "engine/gl/drawn_lights.h"
#include "engine/gl/render_target.h"
#include "engine/gl/light_constants.h"
#include "engine/gl/renderer.h"
#include "engine/gl/shadow_maps.h"
#include "gl/test_context.h"
#include "support/gltf_builder.h"
#include "support/sun_map.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 320, kHeight = 180;
constexpr float kSunRadiusDegrees = 3.0f;
constexpr float kSunRadiance = 2000.0f;  // irradiance 17.2 head-on
constexpr float kSky = 0.5f;             // irradiance 1.57 on the open ground

struct SunScene {
  fs::path dir, scene;
  glm::vec3 sun;       // unit, towards the sun
  float sphereY;       // the sphere's centre (radius 0.5) above the ground at y = 0
  float sunRadiusDegrees = kSunRadiusDegrees;
};

glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees) {
  const float a = glm::radians(azimuthDegrees), e = glm::radians(elevationDegrees);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

// The map (1024 x 512, 4 x 4 samples per texel: the disk's rim antialiased) and scene.json with
// `models`, by default the sphere of radius 0.5 at height sphereY.
SunScene writeSunScene(const std::string& name, glm::vec3 sun, float sphereY, nlohmann::json models = nullptr,
                       float sunRadiusDegrees = kSunRadiusDegrees) {
  SunScene s{test::scratchDir() / name, {}, sun, sphereY, sunRadiusDegrees};
  fs::create_directories(s.dir);
  const float cosRadius = std::cos(glm::radians(sunRadiusDegrees));
  const Image map = latLongFromRadiance(1024, 512, 4, [&](const glm::vec3& d) {
    return glm::vec3(kSky + (glm::dot(d, sun) >= cosRadius ? kSunRadiance : 0.0f));
  });
  writeExr(s.dir / "sun.exr", map, {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
  const nlohmann::json scene = {
      {"models", models.is_null() ? nlohmann::json{{{"shape", "sphere"}, {"translation", {0.0, sphereY, 0.0}}, {"scale", 0.5}}}
                                  : models},
      {"ground", {{"height", 0.0}, {"size", 6.0}}},
      {"environment", {{"file", "sun.exr"}}},
      {"camera", {{"position", {0.0, 2.6, 5.0}}, {"target", {0.3, 0.3, 0.0}}, {"yfov", 40.0}}},
      {"width", kWidth},
      {"height", kHeight}};
  s.scene = s.dir / "scene.json";
  std::ofstream(s.scene) << scene.dump(2);
  return s;
}

// The scene baked in memory, with the sun as its one light and the uniform sky as the residual
// (what sun extraction gives for this map; written by hand so that the test states the answer).
BakedScene bakeWithSun(const SunScene& s) {
  InMemoryBakeOptions options;
  options.aoRays = 32;
  BakedScene bake = loadOrBakeScene(s.scene, options);
  const EnvironmentStages sky = computeEnvironmentStages(
      EnvironmentMap::fromImage(latLongFromRadiance(64, 32, 1, [](const glm::vec3&) { return glm::vec3(kSky); }), "sky"),
      kViewerEnvironmentStages);
  EnvironmentLight light = test::diskLight({s.sun, glm::radians(s.sunRadiusDegrees), glm::vec3(kSunRadiance)});
  for (int k = 0; k < kShCoefficients; ++k)
    light.sh9.coefficients[std::size_t(k)] = bake.env.sh9.coefficients[std::size_t(k)] - sky.sh9.coefficients[std::size_t(k)];
  bake.env.lights.suns = {light};
  bake.env.residualSh9 = sky.sh9;
  bake.env.residualSpecular = sky.specular;
  return bake;
}

Image renderEngine(Renderer& renderer, const BakedScene& bake, ShadingMode mode) {
  RenderTarget target(kWidth, kHeight, 4);
  FrameSettings settings;
  settings.mode = mode;
  settings.drawSky = false;
  renderer.render(sceneCamera(bake.scene, float(kWidth) / float(kHeight)), settings, target.framebuffer(), kWidth,
                  kHeight);
  target.resolve();
  Image image = target.readColor();
  checkGlErrors("shadow test render");
  return image;
}

// `maxDepth` 2: the direct light and one bounce (the shadows' tests); more for the bounce light's.
Image renderTrace(const SunScene& s, int maxDepth = 2) {
  const fs::path out = s.dir / "trace.exr";
  std::string output;
  const std::string command = test::shellQuoted(test::binDir() / "iblkit-trace") + " " + test::shellQuoted(s.scene) +
                              " -o " + test::shellQuoted(out) + " --spp 96 --max-depth " + std::to_string(maxDepth) +
                              " --seed 3 2>&1";
  EXPECT_EQ(test::runCommand(command, &output), 0) << command << "\n" << output;
  return readExr(out);
}

// The raster position of world point p (the core camera's projection, row 0 at the top).
glm::vec2 project(const BakedScene& bake, const glm::vec3& p) {
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  const glm::vec4 clip = camera.projectionMatrix(float(kWidth) / float(kHeight)) * camera.viewMatrix() * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight};
}

// Mean luminance of rows y - 2 .. y + 2 at every x.
std::vector<float> rowProfile(const Image& image, int y) {
  std::vector<float> profile(std::size_t(image.width()), 0.0f);
  for (int x = 0; x < image.width(); ++x)
    for (int dy = -2; dy <= 2; ++dy) profile[std::size_t(x)] += luminance(glm::vec3(image.at(x, y + dy))) / 5.0f;
  return profile;
}

struct Edge {
  float position = 0.0f;  // x where the profile crosses half-way from the umbra to the lit level
  float width = 0.0f;     // |x(90%) - x(10%)|
};

// The edge from the umbra at `centre` walking by `step` (+1 right, -1 left) to the lit level read
// `litOffset` pixels beyond the 50% crossing.
Edge findEdge(const std::vector<float>& profile, int centre, int step) {
  const float umbra = profile[std::size_t(centre)];
  float lit = umbra;
  for (int x = centre; x >= 0 && x < int(profile.size()); x += step) lit = std::max(lit, profile[std::size_t(x)]);
  auto crossing = [&](float fraction) {
    const float level = umbra + fraction * (lit - umbra);
    for (int x = centre; x + step >= 0 && x + step < int(profile.size()); x += step) {
      const float a = profile[std::size_t(x)], b = profile[std::size_t(x + step)];
      if (a < level && b >= level) return float(x) + 0.5f + float(step) * (level - a) / (b - a);
    }
    return -1.0f;
  };
  return {crossing(0.5f), std::abs(crossing(0.9f) - crossing(0.1f))};
}

class ShadowTest : public ::testing::Test {
 protected:
  void SetUp() override { test::glContext(); }
};

TEST_F(ShadowTest, SphereShadowEdgesAndPenumbraMatchTheReference) {
  // Sun from -X, 55 degrees up: the shadow's centre is on the ground at x = 1 / tan(55) = 0.70.
  const SunScene s = writeSunScene("shadow_sphere", sunDirection(-90.0f, 55.0f), 1.0f);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s);
  const glm::vec2 centre = project(bake, {1.0f / std::tan(glm::radians(55.0f)), 0.0f, 0.0f});
  const int row = int(centre.y);
  const std::vector<float> a = rowProfile(engine, row), b = rowProfile(reference, row);
  for (int step : {-1, 1}) {
    const Edge e = findEdge(a, int(centre.x), step), r = findEdge(b, int(centre.x), step);
    std::cout << (step < 0 ? "near" : "far") << " edge: engine x " << e.position << " width " << e.width
              << ", reference x " << r.position << " width " << r.width << '\n';
    EXPECT_GT(r.position, 0.0f);
    EXPECT_NEAR(e.position, r.position, 2.0f);
    EXPECT_NEAR(e.width, r.width, 2.0f);
  }
}

// A tall object under a large sun (a column of three spheres 1.8 high, a 4 degree sun 40 degrees
// up, like studio's 3.2 degree softbox): its long shadow's far end has a penumbra tens of texels
// wide, whose filter footprint also covers the ground beyond the shadow. Over 4 x 4-pixel blocks
// of the ground around the shadow, the engine's mean luminance against the reference's, in units
// of the lit ground's: no block off by more than 0.11, a mean error below 0.019 (measured: 0.066
// and 0.0133; 0.077 and 0.0153 before kPenumbraFilterScale). When the maps' depth ran along the light (before the ground set it), the ground's
// ramp across a wide footprint dominated its exponential moment, and lit blocks with staircase
// edges (the map's coarse texels) showed inside the shadow: 0.158 and 0.0223.
TEST_F(ShadowTest, LongShadowOfALargeSunHasNoLitBlocks) {
  nlohmann::json column = nlohmann::json::array();
  for (int k = 0; k < 3; ++k) column.push_back({{"shape", "sphere"}, {"translation", {-1.0, 0.3 + 0.6 * k, 1.0}}, {"scale", 0.3}});
  const SunScene s = writeSunScene("large_sun", sunDirection(-100.0f, 40.0f), 1.0f, column, 4.0f);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s);
  // The shadow lies along +x (the sun is from -x, 10 degrees towards -z): its box on the ground,
  // with a margin for the penumbra, projected to the image.
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec3 corner : {glm::vec3(-1.4f, 0.0f, 0.2f), glm::vec3(-1.4f, 0.0f, 1.8f), glm::vec3(1.6f, 0.0f, 0.2f),
                                 glm::vec3(1.6f, 0.0f, 1.8f)}) {
    lo = glm::min(lo, project(bake, corner));
    hi = glm::max(hi, project(bake, corner));
  }
  constexpr int kBlock = 4;
  float lit = 0.0f;
  for (int y = int(lo.y); y < int(hi.y); ++y)
    for (int x = int(lo.x); x < int(hi.x); ++x) lit = std::max(lit, luminance(glm::vec3(reference.at(x, y))));
  ASSERT_GT(lit, 0.0f);
  int blocks = 0;
  double worst = 0.0, sum = 0.0;
  for (int by = int(lo.y); by + kBlock <= int(hi.y); by += kBlock)
    for (int bx = int(lo.x); bx + kBlock <= int(hi.x); bx += kBlock) {
      double e = 0.0, r = 0.0;
      bool ground = true;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) {
          ground = ground && engine.at(x, y).a == 0.0f && luminance(glm::vec3(engine.at(x, y))) > 0.0f;
          e += luminance(glm::vec3(engine.at(x, y)));
          r += luminance(glm::vec3(reference.at(x, y)));
        }
      if (!ground) continue;  // a sphere's pixel, or beyond the ground
      const double error = std::abs(e - r) / (kBlock * kBlock * double(lit));
      worst = std::max(worst, error);
      sum += error;
      ++blocks;
    }
  std::cout << blocks << " blocks of the ground around the shadow: |engine - reference| / lit ground, max " << worst
            << " mean " << sum / std::max(blocks, 1) << '\n';
  EXPECT_GT(blocks, 200);
  EXPECT_LT(worst, 0.11);
  EXPECT_LT(sum / std::max(blocks, 1), 0.019);
}

// A small caster high above the ground (a sphere of radius 0.18 whose centre is 2.2 up, a 3 degree
// sun 70 degrees up): its shadow is a blob not much wider than its penumbra (a half width of about
// 0.11 against the ball's 0.18), the case of the bunny's head and ears under `studio`. The
// reference's blob has a dark core, the sky alone; the engine's filter (shadow.glsl,
// kPenumbraFilterScale) must not reach far past the blob from its centre. Over a 3 x 3-pixel box
// at the blob's centre, luminance over the lit ground's: the engine within 0.05 of the reference
// (measured: reference 0.090; engine 0.130 with kPenumbraFilterScale 1.25, 0.156 with 1, the
// B-spline of the disk's own deviation, 0.109 with 1.5). What is left above the reference is the
// blocker search's mean depth over the ball's near side.
TEST_F(ShadowTest, AHighSmallCastersShadowKeepsItsCore) {
  const nlohmann::json ball = {{{"shape", "sphere"}, {"translation", {0.0, 2.2, 0.0}}, {"scale", 0.18}}};
  const glm::vec3 sun = sunDirection(-90.0f, 70.0f);
  const SunScene s = writeSunScene("high_ball", sun, 2.2f, ball);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s);
  const glm::vec3 centre = glm::vec3(0.0f, 2.2f, 0.0f) - sun * (2.2f / sun.y);
  const glm::vec2 c = project(bake, centre), lit = project(bake, centre + glm::vec3(0.0f, 0.0f, 1.2f));
  auto box = [](const Image& image, glm::vec2 at) {
    float sum = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) sum += luminance(glm::vec3(image.at(int(at.x) + dx, int(at.y) + dy)));
    return sum / 9.0f;
  };
  const float e = box(engine, c) / box(engine, lit), r = box(reference, c) / box(reference, lit);
  std::cout << "the blob's centre over the lit ground: engine " << e << ", reference " << r << '\n';
  EXPECT_LT(r, 0.2f);  // the reference has a core: the sky alone is 0.08 of the lit ground
  EXPECT_NEAR(e, r, 0.05f);
}

// Where the camera ray through pixel (x, y)'s centre meets the ground y = 0 (false above the horizon).
bool groundPoint(const BakedScene& bake, int x, int y, glm::vec3& point) {
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  const Ray ray = camera.primaryRay(glm::vec2(x + 0.5f, y + 0.5f), kWidth, kHeight);
  if (ray.direction.y >= 0.0f) return false;
  point = ray.origin - ray.direction * (ray.origin.y / ray.direction.y);
  return true;
}

// Whether the whole sun is visible from `p` with a margin: the angle between the sun and the sphere
// (radius 0.5 at (0, sphereY, 0)) exceeds the sphere's angular radius plus the sun's plus 2 degrees.
bool wholeSunVisible(const SunScene& s, const glm::vec3& p) {
  const glm::vec3 toSphere = glm::vec3(0.0f, s.sphereY, 0.0f) - p;
  const float distance = glm::length(toSphere);
  if (distance <= 0.5f) return false;
  const float angle = std::acos(std::clamp(glm::dot(toSphere / distance, s.sun), -1.0f, 1.0f));
  return angle > std::asin(0.5f / distance) + glm::radians(kSunRadiusDegrees + 2.0f);
}

struct AcneCheck {
  int pixels = 0;
  float minRatio = 1.0f, meanRatio = 0.0f;
};

// Shadowed over unshadowed radiance on the ground pixels (and the sphere's, lit side) that see the
// whole sun: 1 without acne.
AcneCheck shadowedOverUnshadowedWhereLit(const SunScene& s, const BakedScene& bake, Renderer& renderer) {
  const Image shadowed = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image unshadowed = renderEngine(renderer, bake, ShadingMode::Lights);
  AcneCheck check;
  // Pixels whose 3 x 3 neighbourhood is ground only (no silhouette of the sphere).
  auto groundOnly = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const glm::vec4 c = unshadowed.at(x + dx, y + dy);
        if (c.a != 0.0f || luminance(glm::vec3(c)) <= 0.0f) return false;
      }
    return true;
  };
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x) {
      glm::vec3 p;
      if (!groundOnly(x, y) || !groundPoint(bake, x, y, p) || !wholeSunVisible(s, p)) continue;
      const float ratio = luminance(glm::vec3(shadowed.at(x, y))) / luminance(glm::vec3(unshadowed.at(x, y)));
      check.minRatio = std::min(check.minRatio, ratio);
      check.meanRatio += ratio;
      ++check.pixels;
    }
  if (check.pixels) check.meanRatio /= float(check.pixels);
  return check;
}

TEST_F(ShadowTest, NoAcneOnTheLitGroundFromHighAndGrazingSun) {
  for (float elevation : {55.0f, 10.0f}) {
    const SunScene s = writeSunScene("acne_" + std::to_string(int(elevation)), sunDirection(-60.0f, elevation), 1.0f);
    const BakedScene bake = bakeWithSun(s);
    Renderer renderer(bake);
    const AcneCheck check = shadowedOverUnshadowedWhereLit(s, bake, renderer);
    std::cout << "sun " << elevation << " degrees up: " << check.pixels << " lit ground pixels, shadowed / unshadowed min "
              << check.minRatio << " mean " << check.meanRatio << '\n';
    EXPECT_GT(check.pixels, 10000);
    EXPECT_GT(check.minRatio, 0.99f);
    EXPECT_GT(check.meanRatio, 0.999f);
  }
}

// The maps' depth (fitShadowFrame) on a planar ground is measured from the ground's plane: every
// ground vertex under the map has one depth, and at a fixed (u, v) a point moved by delta towards
// the light still moves by delta over the depth range, as with the depth along the light; the
// objects fit in [0, 1]. Without a ground, or on one that is not planar, the depth runs along the
// light, and the ground's vertices spread over a ramp.
TEST(ShadowFrame, DepthIsMeasuredFromAPlanarGroundAndKeepsSeparationsAlongTheLight) {
  Mesh ground = toMesh(gridPlane(glm::vec3(0.0f), 6.0f, 8), "ground");
  ground.isGround = true;
  const Mesh sphere = toMesh(uvSphere(glm::vec3(0.2f, 1.0f, -0.1f), 0.5f, 16, 32), "sphere");
  const glm::vec3 sun = sunDirection(-60.0f, 35.0f);
  const ShadowLight light{sun, std::tan(glm::radians(2.0f))};
  auto depth = [](const ShadowFrame& frame, const glm::vec3& p) { return (frame.shadowFromWorld * glm::vec4(p, 1.0f)).z; };
  auto groundDepthSpread = [&](const ShadowFrame& frame) {
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : ground.positions) {
      const glm::vec2 uv(frame.shadowFromWorld * glm::vec4(p, 1.0f));
      if (glm::any(glm::lessThan(uv, glm::vec2(0.0f))) || glm::any(glm::greaterThan(uv, glm::vec2(1.0f)))) continue;
      lo = std::min(lo, depth(frame, p));
      hi = std::max(hi, depth(frame, p));
    }
    return hi - lo;
  };
  const ShadowFrame flat = fitShadowFrame({sphere, ground}, light, kShadowMapSize);
  EXPECT_LT(groundDepthSpread(flat), 1e-5f);
  for (const glm::vec3& p : sphere.positions) {
    EXPECT_GE(depth(flat, p), 0.0f);
    EXPECT_LE(depth(flat, p), 1.0f);
  }
  Mesh bumpy = ground;
  bumpy.positions[bumpy.positions.size() / 2].y += 0.3f;  // no longer planar
  const ShadowFrame alongLight = fitShadowFrame({sphere, bumpy}, light, kShadowMapSize);
  EXPECT_GT(groundDepthSpread(alongLight), 0.1f);
  for (const ShadowFrame& frame : {flat, alongLight, fitShadowFrame({sphere}, light, kShadowMapSize)}) {
    const glm::vec3 p(0.4f, 0.7f, 0.3f);
    constexpr float kDelta = 0.25f;
    const glm::vec4 a = frame.shadowFromWorld * glm::vec4(p, 1.0f), b = frame.shadowFromWorld * glm::vec4(p + kDelta * sun, 1.0f);
    EXPECT_NEAR(b.x, a.x, 1e-6f);
    EXPECT_NEAR(b.y, a.y, 1e-6f);
    EXPECT_NEAR((a.z - b.z) * frame.extent.z, kDelta, 1e-5f);  // depth 0 towards the light
  }
  // The plane correction's slope: 0 on the flat ground in its own frame, tan of the light's angle
  // to the normal where the depth runs along the light.
  const glm::vec3 h = flat.slopeFromNormal * glm::vec3(0.0f, 1.0f, 0.0f), k = alongLight.slopeFromNormal * glm::vec3(0.0f, 1.0f, 0.0f);
  EXPECT_LT(glm::length(glm::vec2(h)) / std::abs(h.z), 1e-5f);
  EXPECT_NEAR(glm::length(glm::vec2(k)) / std::abs(k.z), 1.0f / std::tan(glm::radians(35.0f)), 1e-4f);
}

// A sphere (radius 0.5, centre 0.7 above the ground) and a 1 x 1 double-sided wall of glTF alpha
// mode `alphaMode` (BLEND with alpha 0.6) beside it, under `sun` (the shadow mask's and the
// ground visibility's scene).
SunScene writeSphereAndWallScene(const std::string& name, glm::vec3 sun, const std::string& alphaMode = "OPAQUE") {
  const nlohmann::json models = {{{"shape", "sphere"}, {"translation", {0.6, 0.7, 0.0}}, {"scale", 0.5}},
                                 {{"file", "wall.gltf"}, {"translation", {-0.6, 0.5, 0.3}}}};
  const SunScene s = writeSunScene(name, sun, 0.7f, models);
  test::GltfBuilder builder;
  builder.addQuadNode(0.5f);
  builder.document()["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, alphaMode == "BLEND" ? 0.6 : 1.0}}, {"metallicFactor", 0.0}}},
       {"doubleSided", true},
       {"alphaMode", alphaMode}}};
  builder.write(s.dir / "wall.gltf", test::GltfBuilder::Storage::BinFile);
  return s;
}

// `settings` without the sky into a fresh kWidth x kHeight target of `samples` samples.
Image renderFrame(Renderer& renderer, const Camera& camera, FrameSettings settings, int samples) {
  RenderTarget target(kWidth, kHeight, samples);
  settings.drawSky = false;
  renderer.render(camera, settings, target.framebuffer(), kWidth, kHeight);
  return target.readColor();
}

// The ground's visibility texture's frame (fitGroundVisibility): on the ground's plane, over every
// point of the plane that some light's map covers (so that outside it no light is shadowed and the
// edge texels, lit, stand for it), cut to the ground; texels no larger than the finest map's
// unless the cap binds; none without a planar ground or without objects.
TEST(GroundVisibility, TheFrameCoversWhatTheMapsCoverOnThePlane) {
  Mesh ground = toMesh(gridPlane(glm::vec3(0.0f), 6.0f, 8), "ground");
  ground.isGround = true;
  const Mesh sphere = toMesh(uvSphere(glm::vec3(0.2f, 1.0f, -0.1f), 0.5f, 16, 32), "sphere");
  const std::vector<ShadowLight> lights = {{sunDirection(-60.0f, 35.0f), std::tan(glm::radians(2.0f))},
                                           {sunDirection(100.0f, 70.0f), std::tan(glm::radians(0.5f))}};
  const std::vector<Mesh> meshes = {sphere, ground};
  std::vector<ShadowFrame> frames;
  for (const ShadowLight& light : lights) frames.push_back(fitShadowFrame(meshes, light, kShadowMapSize));
  const GroundVisibilityFrame g = fitGroundVisibility(meshes, lights, frames, kGroundVisibilityMaxSize);
  ASSERT_TRUE(g.valid());
  EXPECT_LE(std::max(g.width, g.height), kGroundVisibilityMaxSize);
  EXPECT_NEAR(std::abs(glm::dot(g.normal, glm::vec3(0.0f, 1.0f, 0.0f))), 1.0f, 1e-6f);
  EXPECT_NEAR(g.origin.y, 0.0f, 1e-5f);
  // The texel's sides: along the plane, and the two axes' (u, v) inverses of them.
  EXPECT_NEAR(glm::dot(g.stepU, g.normal), 0.0f, 1e-7f);
  EXPECT_NEAR(glm::dot(g.uFromWorld, g.stepU) * float(g.width), 1.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(g.vFromWorld, g.stepV) * float(g.height), 1.0f, 1e-4f);
  const float finest = std::min(frames[0].extent.w, frames[1].extent.w);
  if (std::max(g.width, g.height) < kGroundVisibilityMaxSize) {
    EXPECT_LE(glm::length(g.stepU), finest * 1.0001f);
    EXPECT_LE(glm::length(g.stepV), finest * 1.0001f);
  }
  // Every ground point inside some map's square is inside the texture; the texture's own corners lie
  // on the ground.
  int inside = 0;
  for (int j = 0; j <= 60; ++j)
    for (int i = 0; i <= 60; ++i) {
      const glm::vec3 p(-3.0f + 0.1f * float(i), 0.0f, -3.0f + 0.1f * float(j));
      bool covered = false;
      for (const ShadowFrame& frame : frames) {
        const glm::vec2 uv(frame.shadowFromWorld * glm::vec4(p, 1.0f));
        covered = covered || (uv.x >= 0.0f && uv.y >= 0.0f && uv.x <= 1.0f && uv.y <= 1.0f);
      }
      if (!covered) continue;
      ++inside;
      const glm::vec2 st(glm::dot(g.uFromWorld, p - g.origin), glm::dot(g.vFromWorld, p - g.origin));
      EXPECT_TRUE(st.x >= -1e-4f && st.y >= -1e-4f && st.x <= 1.0001f && st.y <= 1.0001f) << p.x << ", " << p.z;
    }
  EXPECT_GT(inside, 20);
  const glm::vec3 far = g.origin + float(g.width) * g.stepU + float(g.height) * g.stepV;
  EXPECT_LE(std::max(std::abs(far.x), std::abs(far.z)), 3.0001f);
  EXPECT_LE(std::max(std::abs(g.origin.x), std::abs(g.origin.z)), 3.0001f);
  // No plane, no objects, no texture.
  Mesh bumpy = ground;
  bumpy.positions[bumpy.positions.size() / 2].y += 0.3f;
  EXPECT_FALSE(fitGroundVisibility({sphere, bumpy}, lights, frames, kGroundVisibilityMaxSize).valid());
  EXPECT_FALSE(fitGroundVisibility({ground}, lights, frames, kGroundVisibilityMaxSize).valid());
}

// The ground's shadows read from its visibility texture (FrameSettings::groundVisibility) against
// the same frame computed per pixel in the lit pass: the same shadows on the ground within the
// texture's bilinear interpolation, the objects untouched. Suns high, grazing (12 degrees: a
// long shadow, the texture's cap binds) and behind the camera; a sphere and a wall.
TEST_F(ShadowTest, TheGroundsVisibilityTextureGivesThePerPixelShadows) {
  struct Sun {
    float azimuth, elevation;
  };
  for (const Sun sun : {Sun{150.0f, 50.0f}, Sun{150.0f, 12.0f}, Sun{0.0f, 20.0f}, Sun{-70.0f, 35.0f}}) {
    const std::string name = "ground_visibility_" + std::to_string(int(sun.azimuth)) + "_" + std::to_string(int(sun.elevation));
    const SunScene s = writeSphereAndWallScene(name, sunDirection(sun.azimuth, sun.elevation));
    const BakedScene bake = bakeWithSun(s);
    Renderer renderer(bake);
    const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
    auto frame = [&](ShadingMode mode, bool groundVisibility, bool mask) {
      FrameSettings settings;
      settings.mode = mode;
      settings.shadowMask = mask;
      settings.groundVisibility = groundVisibility;
      return renderFrame(renderer, camera, settings, 1);
    };
    const Image perPixel = frame(ShadingMode::LightsShadowed, false, false);
    EXPECT_EQ(renderer.groundVisibilityFrames(), 0);
    const Image fromTexture = frame(ShadingMode::LightsShadowed, true, false);
    EXPECT_EQ(renderer.groundVisibilityFrames(), 1);
    const Image withMask = frame(ShadingMode::LightsShadowed, true, true);
    EXPECT_EQ(renderer.groundVisibilityFrames(), 2);
    const Image unshadowed = frame(ShadingMode::Lights, true, false);
    checkGlErrors("ground visibility frames");
    int ground = 0, shadowed = 0, shadowedFromTexture = 0, off = 0;
    double sum = 0.0, objectsWorst = 0.0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const glm::vec3 a(perPixel.at(x, y)), b(fromTexture.at(x, y));
        const float lit = luminance(glm::vec3(unshadowed.at(x, y)));
        if (lit <= 0.0f) continue;  // nothing drawn
        const double difference = glm::length(a - b) / std::max(glm::length(a), 1e-3f);
        if (perPixel.at(x, y).a > 0.5f) {  // an object: the lit pass's lookups either way
          objectsWorst = std::max(objectsWorst, difference);
          continue;
        }
        ++ground;
        sum += difference;
        if (difference > 0.1) ++off;
        if (luminance(a) < 0.5f * lit) ++shadowed;
        if (luminance(b) < 0.5f * lit) ++shadowedFromTexture;
        // The mask's frame reads the same texture on the ground.
        EXPECT_LT(glm::length(glm::vec3(withMask.at(x, y)) - b), 1e-4f * std::max(glm::length(b), 1.0f)) << x << ", " << y;
      }
    const double mean = sum / std::max(ground, 1), offFraction = double(off) / std::max(ground, 1);
    std::cout << "sun at azimuth " << sun.azimuth << ", " << sun.elevation << " degrees up: " << shadowed
              << " shadowed ground pixels per pixel, " << shadowedFromTexture << " from the texture; mean relative "
              << "difference " << mean << ", " << 100.0 * offFraction << "% of " << ground
              << " ground pixels off by more than 10%; objects' largest difference " << objectsWorst << "\n";
    // Behind the camera the shadows fall behind the objects: a few pixels in view.
    if (sun.azimuth != 0.0f) {
      EXPECT_GT(shadowed, 300);
    }
    EXPECT_NEAR(shadowedFromTexture, shadowed, 0.02 * shadowed + 5);
    EXPECT_LT(mean, 0.005);
    EXPECT_LT(offFraction, 0.005);
    EXPECT_LT(objectsWorst, 1e-5);
  }
}

// The ground's triangles split by the maps' cover (shadowCoverage): every triangle in exactly one
// part, the covered ones overlapping a map's square and the others not, the ground where the
// sphere's shadow falls covered, and most of the 6 x 6 ground (the far part, which the renderer
// draws without the shadow lookups) not. The shadow tests above and below render through the
// split, so they fail too if it leaves a shadowed triangle out.
TEST_F(ShadowTest, GroundOutsideTheMapsIsSplitFromTheShadowedGround) {
  const SunScene s = writeSunScene("coverage", sunDirection(-60.0f, 55.0f), 1.0f);
  const BakedScene bake = bakeWithSun(s);
  const ShadowFrame frame = fitShadowFrame(bake.scene.meshes, {s.sun, std::tan(glm::radians(kSunRadiusDegrees))}, kShadowMapSize);
  const auto ground = std::find_if(bake.scene.meshes.begin(), bake.scene.meshes.end(), [](const Mesh& m) { return m.isGround; });
  ASSERT_NE(ground, bake.scene.meshes.end());
  const ShadowCoverage coverage = shadowCoverage(*ground, {frame});
  std::vector<int> seen(ground->triangleCount(), 0);
  std::size_t covered = 0;
  const auto boxOverlapsTheSquare = [&](std::size_t t) {
    glm::vec2 low(1e30f), high(-1e30f);
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = glm::vec3(frame.shadowFromWorld * glm::vec4(ground->positions[ground->indices[3 * t + std::size_t(k)]], 1.0f));
      low = glm::min(low, glm::vec2(p));
      high = glm::max(high, glm::vec2(p));
    }
    return high.x >= 0.0f && high.y >= 0.0f && low.x <= 1.0f && low.y <= 1.0f;
  };
  for (const bool inside : {true, false})
    for (const TriangleRun& run : inside ? coverage.covered : coverage.uncovered)
      for (std::size_t t = run.first; t < run.first + run.count; ++t) {
        ASSERT_LT(t, seen.size());
        ++seen[t];
        EXPECT_EQ(boxOverlapsTheSquare(t), inside) << "triangle " << t;
        covered += inside;
      }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  // The shadow's centre on the ground: the sphere's centre moved along -sun down to y = 0.
  const glm::vec3 shadowCentre = glm::vec3(0.0f, s.sphereY, 0.0f) - s.sun * (s.sphereY / s.sun.y);
  bool centreCovered = false;
  for (const TriangleRun& run : coverage.covered)
    for (std::size_t t = run.first; t < run.first + run.count; ++t) {
      glm::vec3 c[3];
      for (int k = 0; k < 3; ++k) c[k] = ground->positions[ground->indices[3 * t + std::size_t(k)]];
      // Inside the triangle in x, z (barycentric signs).
      const auto edge = [&](const glm::vec3& a, const glm::vec3& b) {
        return (b.x - a.x) * (shadowCentre.z - a.z) - (b.z - a.z) * (shadowCentre.x - a.x);
      };
      const float e0 = edge(c[0], c[1]), e1 = edge(c[1], c[2]), e2 = edge(c[2], c[0]);
      if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) centreCovered = true;
    }
  EXPECT_TRUE(centreCovered);
  std::cout << covered << " of " << seen.size() << " ground triangles covered, in " << coverage.covered.size()
            << " runs\n";
  EXPECT_GT(covered, 0u);
  EXPECT_LT(covered, seen.size() / 2);
}

// The maps depend on the lights only: frames from other cameras render none; a turned environment
// (the light's direction moves) and a new environment render them again; unshadowed modes none.
TEST_F(ShadowTest, ShadowMapsAreRenderedOnlyWhenALightChanges) {
  const SunScene s = writeSunScene("renders", sunDirection(-90.0f, 55.0f), 1.0f);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  RenderTarget target(64, 36, 1);
  FrameSettings settings;
  settings.mode = ShadingMode::Lights;
  Camera camera = sceneCamera(bake.scene, 16.0f / 9.0f);
  renderer.render(camera, settings, target.framebuffer(), 64, 36);
  EXPECT_EQ(renderer.shadowMapRenders(), 0);
  settings.mode = ShadingMode::LightsShadowed;
  for (int frame = 0; frame < 3; ++frame) {
    camera.position += glm::vec3(0.3f, 0.1f, -0.2f);
    renderer.render(camera, settings, target.framebuffer(), 64, 36);
  }
  EXPECT_EQ(renderer.shadowMapRenders(), 1);
  settings.envRotationDegrees = 30.0f;
  renderer.render(camera, settings, target.framebuffer(), 64, 36);
  EXPECT_EQ(renderer.shadowMapRenders(), 2);
  settings.shadows = false;  // drawn as lights
  renderer.render(camera, settings, target.framebuffer(), 64, 36);
  settings.shadows = true;
  renderer.render(camera, settings, target.framebuffer(), 64, 36);
  EXPECT_EQ(renderer.shadowMapRenders(), 2);
  renderer.setEnvironment(bake.env);
  renderer.render(camera, settings, target.framebuffer(), 64, 36);
  EXPECT_EQ(renderer.shadowMapRenders(), 3);
  checkGlErrors("shadow map renders");
}

// The screen-space shadow mask (shadow_mask.h, FrameSettings::shadowMask) gives the frame that the
// shadows computed in the lit pass give: single-sample frames of a sphere and a double-sided wall
// under a high and a grazing sun agree to a relative 1e-3 at every pixel, the lit ground and both
// shadows included (a mask a pixel off, or another surface's, differs by the whole shadow at its
// edges). The wall is OPAQUE, MASK with alpha 1 (drawn opaque, drawnAlphaMode: a receiver of the
// mask too) or BLEND with alpha 0.6 (it keeps its shadows in the lit pass, and the receivers seen
// through its uncovered pixels read the mask). Frames of 4 samples keep the lit pass's shadows.
// The half-resolution mask (shadowMaskDivisor 2, upsampled with its depths) gives the same frame
// but for the pixels within a mask pixel of an edge: a penumbra is interpolated between mask
// pixels 2 frame pixels apart, and a silhouette's pixel may take its visibility from a mask pixel
// of its own surface up to 2 pixels away. Its mean relative difference stays under 2% (1.6%
// measured) and at most 3% of the pixels differ by more than 10% (2.5%), the edges of the shadows;
// under a sun behind the camera the lit objects' silhouettes, seen against the ground in their
// shadow, keep their light: upsampling without the depth test (every mask pixel kept) gives 16 of
// their pixels the ground's shadow.
TEST_F(ShadowTest, ShadowMaskGivesTheLitPassShadows) {
  struct Sun {
    float azimuth, elevation;
  };
  for (const char* alphaMode : {"OPAQUE", "MASK", "BLEND"})
    for (const Sun sun : {Sun{150.0f, 50.0f}, Sun{150.0f, 12.0f}, Sun{0.0f, 20.0f}}) {
      const float elevation = sun.elevation;
      const std::string name = std::string("mask_") + alphaMode + "_" + std::to_string(int(sun.azimuth)) + "_" +
                               std::to_string(int(elevation));
      const SunScene s = writeSphereAndWallScene(name, sunDirection(sun.azimuth, elevation), alphaMode);
      const BakedScene bake = bakeWithSun(s);
      Renderer renderer(bake);
      const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
      auto frame = [&](ShadingMode mode, bool mask, int samples, int divisor = 1) {
        FrameSettings settings;
        settings.mode = mode;
        settings.shadowMask = mask;
        settings.shadowMaskDivisor = divisor;
        // The ground through the mask too (its visibility texture has a test of its own).
        settings.groundVisibility = false;
        return renderFrame(renderer, camera, settings, samples);
      };
      const Image inLitPass = frame(ShadingMode::LightsShadowed, false, 1);
      EXPECT_EQ(renderer.shadowMaskFrames(), 0);
      const Image fromMask = frame(ShadingMode::LightsShadowed, true, 1);
      EXPECT_EQ(renderer.shadowMaskFrames(), 1);
      frame(ShadingMode::LightsShadowed, true, 4);
      EXPECT_EQ(renderer.shadowMaskFrames(), 1);
      const Image unshadowed = frame(ShadingMode::Lights, true, 1);
      const Image fromHalfMask = frame(ShadingMode::LightsShadowed, true, 1, 2);
      EXPECT_EQ(renderer.shadowMaskFrames(), 2);
      checkGlErrors("shadow mask frames");
      int shadowed = 0, shadowedHalf = 0, drawn = 0, halfOff = 0, objects = 0, objectsOff = 0;
      double worst = 0.0, halfSum = 0.0;
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
          const glm::vec3 a(inLitPass.at(x, y)), b(fromMask.at(x, y)), c(fromHalfMask.at(x, y));
          const float lit = luminance(glm::vec3(unshadowed.at(x, y)));
          if (luminance(a) < 0.5f * lit) ++shadowed;
          if (luminance(c) < 0.5f * lit) ++shadowedHalf;
          worst = std::max(worst, double(glm::length(a - b) / std::max(glm::length(a), 1e-3f)));
          if (lit <= 0.0f) continue;  // no surface drawn
          ++drawn;
          const double half = glm::length(a - c) / std::max(glm::length(a), 1e-3f);
          halfSum += half;
          if (half > 0.1) ++halfOff;
          if (inLitPass.at(x, y).a > 0.5f) {
            ++objects;
            if (half > 0.1) ++objectsOff;
          }
        }
      const double halfMean = halfSum / std::max(drawn, 1), halfOffFraction = double(halfOff) / std::max(drawn, 1);
      std::cout << alphaMode << " wall, sun at azimuth " << sun.azimuth << ", " << elevation << " degrees up: " << shadowed
                << " shadowed pixels, largest relative difference " << worst << "; half-resolution mask: "
                << shadowedHalf << " shadowed, mean relative difference " << halfMean << ", "
                << 100.0 * halfOffFraction << "% of " << drawn << " pixels off by more than 10% (objects: "
                << objectsOff << " of " << objects << ")\n";
      const bool sunBehindCamera = sun.azimuth == 0.0f;
      // Behind the camera the sun leaves little shadow in view (under 1000 pixels, mostly slivers
      // along the silhouettes, which the coarser mask blurs away) and lights the objects' front,
      // whose silhouettes stand against the ground in their own shadow.
      if (!sunBehindCamera) {
        EXPECT_GT(shadowed, 1000);
        EXPECT_NEAR(shadowedHalf, shadowed, 0.03 * shadowed);
      }
      EXPECT_LT(worst, 1e-3);
      EXPECT_LT(halfMean, 0.02);
      EXPECT_LT(halfOffFraction, 0.03);
      // The depth test keeps the ground's shadow off the lit silhouettes: 0 pixels measured (16 of
      // 3852 with every mask pixel kept).
      if (sunBehindCamera) {
        EXPECT_LE(objectsOff, objects / 1000);
      }
    }
}

// The Lambert ground's lights term (a mesh of one normal: its disk irradiance comes from the vertices,
// VERTEX_LIGHTS, renderer.cpp's hasConstantNormal) against the core's formula: doubling the sun's
// radiance adds albedo / pi L E_disk(n.l, r) on the open ground, E_disk the core's
// uniformDiskIrradiance, within 1% (the bounce term off the open ground's occluders, also linear
// in the light, is below that). A wrong radius or normal in the vertex shader's irradiance is off
// by far more (cos r for sin r: 19x).
TEST_F(ShadowTest, OpenGroundTakesTheDiskIrradianceOfTheCore) {
  const glm::vec3 sun = sunDirection(-90.0f, 35.0f);
  const SunScene s = writeSunScene("ground_lights", sun, 1.0f);
  // A Lambert ground (specular 0): the materials whose lights term is the diffuse alone.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(s.scene));
  scene["ground"]["material"] = {{"baseColor", {0.6, 0.5, 0.4}}, {"specular", 0.0}};
  std::ofstream(s.scene) << scene.dump(2);
  BakedScene bake = bakeWithSun(s);
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  auto openGround = [&](float radianceScale) {
    BakedScene scaled = bake;
    scaled.env.lights.suns[0].radiance *= radianceScale;
    scaled.env.lights.suns[0].irradiance *= radianceScale;
    Renderer renderer(scaled);
    FrameSettings settings;
    settings.mode = ShadingMode::Lights;
    settings.drawSky = false;
    RenderTarget target(kWidth, kHeight, 1);
    renderer.render(camera, settings, target.framebuffer(), kWidth, kHeight);
    const Image frame = target.readColor();
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = kHeight - 20; y < kHeight - 5; ++y)
      for (int x = 5; x < 40; ++x, ++count) sum += glm::dvec3(glm::vec3(frame.at(x, y)));
    return sum / double(count);
  };
  const glm::dvec3 added = openGround(2.0f) - openGround(1.0f);
  glm::vec3 albedo(0.0f);
  for (const Mesh& mesh : bake.scene.meshes)
    if (mesh.isGround) albedo = bake.scene.materials.at(std::size_t(mesh.material)).baseColor;
  const double expected = double(luminance(albedo)) / glm::pi<double>() * kSunRadiance *
                          double(uniformDiskIrradiance(sun.y, glm::radians(kSunRadiusDegrees)));
  std::cout << "open ground, the sun's term: " << luminance(glm::vec3(added)) << " against the core's " << expected
            << '\n';
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(luminance(glm::vec3(added)) / expected, 1.0, 0.01);
}

// A near-mirror reflects an extracted light's own shape in the lights modes (lights.glsl,
// mirroredDiskRadiance of the light's texels): a lamp 20 x 5 degrees, which sun extraction makes
// one light, the disk of its spread (7.4 degrees), over a mirror sphere. Where the mirror reflects
// the lamp, the lights mode reads the map's chain minus the residual's, the lamp's texels, so it
// matches `full` (which reads the map's chain): the reflected lamp's luminance, summed over the
// sphere's pixels that reflect it in either frame, and pixel by pixel, within 1e-4 of the sum. A
// uniform disk in its place (what it reflected before): the same sum to 0.5%, but pixel by pixel
// off by 102% of it.
TEST_F(ShadowTest, AMirrorReflectsTheLampsOwnShapeInTheLightsModes) {
  const SunScene s{test::scratchDir() / "mirror_lamp", {}, sunDirection(-90.0f, 35.0f), 1.0f};
  fs::create_directories(s.dir);
  const Image map = latLongFromRadiance(1024, 512, 4, [](const glm::vec3& d) {
    const float azimuth = glm::degrees(std::atan2(d.x, d.z)), elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    const bool lamp = std::abs(azimuth + 40.0f) < 10.0f && std::abs(elevation - 30.0f) < 2.5f;
    return glm::vec3(kSky + (lamp ? 300.0f : 0.0f));
  });
  writeExr(s.dir / "lamp.exr", map, {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
  const nlohmann::json scene = {
      {"models", {{{"shape", "sphere"}, {"translation", {0.0, 1.0, 0.0}}, {"scale", 1.0},
                   {"material", {{"baseColor", {1.0, 1.0, 1.0}}, {"metallic", 1.0}, {"roughness", 0.0}}}}}},
      {"ground", {{"height", 0.0}, {"size", 6.0}}},
      {"environment", {{"file", "lamp.exr"}}},
      {"camera", {{"position", {0.0, 1.6, 3.0}}, {"target", {0.0, 1.0, 0.0}}, {"yfov", 40.0}}},
      {"width", kWidth},
      {"height", kHeight}};
  std::ofstream(s.dir / "scene.json") << scene.dump(2);
  InMemoryBakeOptions options;
  options.aoRays = 16;
  const BakedScene bake = loadOrBakeScene(s.dir / "scene.json", options);
  ASSERT_EQ(bake.env.lights.suns.size(), 1u);
  std::cout << "the lamp as a light: angular radius " << glm::degrees(bake.env.lights.suns[0].angularRadius) << " degrees\n";
  Renderer renderer(bake);
  const Image full = renderEngine(renderer, bake, ShadingMode::Full);
  const Image lights = renderEngine(renderer, bake, ShadingMode::Lights);
  // The sphere's pixels reflecting the lamp: 20 times the sky's radiance in either frame.
  double sumFull = 0.0, sumLights = 0.0, sumDifference = 0.0;
  int pixels = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const float a = luminance(glm::vec3(full.at(x, y))), b = luminance(glm::vec3(lights.at(x, y)));
      if (full.at(x, y).a == 0.0f || std::max(a, b) < 20.0f * kSky) continue;
      sumFull += a, sumLights += b, sumDifference += std::abs(a - b);
      ++pixels;
    }
  std::cout << pixels << " pixels reflect the lamp: lights / full " << sumLights / sumFull << ", sum |lights - full| / sum full "
            << sumDifference / sumFull << '\n';
  EXPECT_GT(pixels, 20);
  EXPECT_NEAR(sumLights / sumFull, 1.0, 0.03);
  EXPECT_LT(sumDifference / sumFull, 0.15);
}

// K below the number of suns: a sun not drawn as a light keeps its diffuse light in the residual's
// SH9 (SH is linear). With K = 0 the open ground, far from the sphere, gets the map's SH9 irradiance
// (sky + sun) from the residual alone: within 2% of K = 1's residual + disk light.
TEST_F(ShadowTest, SunsNotDrawnStayInTheResidual) {
  const SunScene s = writeSunScene("k0", sunDirection(-90.0f, 55.0f), 1.0f);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  FrameSettings one, none;
  one.mode = none.mode = ShadingMode::Lights;
  one.drawSky = none.drawSky = false;
  none.lightCount = 0;
  const Camera camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  RenderTarget target(kWidth, kHeight, 1);
  renderer.render(camera, one, target.framebuffer(), kWidth, kHeight);
  const Image withLight = target.readColor();
  renderer.render(camera, none, target.framebuffer(), kWidth, kHeight);
  const Image withoutLight = target.readColor();
  // The ground's front corner region (bottom-left of the frame): far from the sphere, open sky.
  float a = 0.0f, b = 0.0f;
  for (int y = kHeight - 20; y < kHeight - 5; ++y)
    for (int x = 5; x < 40; ++x) {
      a += luminance(glm::vec3(withLight.at(x, y)));
      b += luminance(glm::vec3(withoutLight.at(x, y)));
    }
  std::cout << "open ground, K = 0 over K = 1: " << b / a << '\n';
  EXPECT_GT(a, 0.0f);
  EXPECT_NEAR(b / a, 1.0f, 0.02f);
}

// A wall (a 1 m double-sided square standing on the ground, facing the camera) with the sun behind
// it, 20 degrees up: its shadow starts at its base. The ground 1 to 20 cm in front of the base, in
// the umbra, must be dark (a peter-panning gap would leave a lit line along the base).
TEST_F(ShadowTest, ShadowStartsAtTheContact) {
  const glm::vec3 sun = sunDirection(160.0f, 20.0f);
  const SunScene s = writeSunScene("contact", sun, 0.0f, {{{"file", "wall.gltf"}, {"translation", {0.0, 0.5, 0.0}}}});
  test::GltfBuilder builder;
  builder.addQuadNode(0.5f);
  builder.document()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}}},
                                      {"doubleSided", true}}};
  builder.write(s.dir / "wall.gltf", test::GltfBuilder::Storage::BinFile);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image shadowed = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image unshadowed = renderEngine(renderer, bake, ShadingMode::Lights);
  int checked = 0;
  for (float t = 0.01f; t <= 0.2f; t += 0.01f) {
    const glm::vec2 pixel = project(bake, glm::vec3(0.0f, 0.0f, t));
    const int x = int(pixel.x), y = int(pixel.y);
    const glm::vec4 lit = unshadowed.at(x, y);
    if (lit.a != 0.0f) continue;  // the sphere hides this point
    const float ratio = luminance(glm::vec3(shadowed.at(x, y))) / luminance(glm::vec3(lit));
    std::cout << "contact + " << t << " m: shadowed / unshadowed " << ratio << '\n';
    EXPECT_LT(ratio, 0.25f) << t;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

// The mean luminance of the pixels within +-dx, +-dy of pixel p.
double meanLuminanceAround(const Image& image, glm::vec2 p, int dx, int dy) {
  double sum = 0.0;
  for (int y = int(p.y) - dy; y <= int(p.y) + dy; ++y)
    for (int x = int(p.x) - dx; x <= int(p.x) + dx; ++x) sum += luminance(glm::vec3(image.at(x, y)));
  return sum / double((2 * dx + 1) * (2 * dy + 1));
}

// The sun's bounce off the ground (docs/dominant-lights.md, "Bounce light of the suns"): a point of
// the sphere facing the camera and slightly down, which the high sun does not reach, is lit by the
// sky and the sunlit ground, which the sphere lights back. The bake's sun bounce (bakeSunBounce:
// three bounces) against a reference with every bounce: 0.4% apart; the transfer's estimate that
// stands in without it (the bake's sun bounce dropped) was 3.7% too bright against one bounce.
TEST_F(ShadowTest, SunlitGroundLightsTheSphereFromBelow) {
  const nlohmann::json sphere = {{{"shape", "sphere"}, {"translation", {0.0, 1.5, 0.0}}, {"scale", 0.5},
                                  {"material", {{"baseColor", {0.5, 0.5, 0.5}}, {"metallic", 0.0}, {"roughness", 1.0}, {"specular", 0.0}}}}};
  const SunScene s = writeSunScene("ground_bounce", sunDirection(-90.0f, 80.0f), 1.5f, sphere);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s, 8);
  const glm::vec3 normal = glm::normalize(glm::vec3(0.0f, -0.3f, 0.95f));
  const glm::vec2 p = project(bake, glm::vec3(0.0f, s.sphereY, 0.0f) + 0.5f * normal);
  const double e = meanLuminanceAround(engine, p, 2, 2), r = meanLuminanceAround(reference, p, 2, 2);
  std::cout << "engine " << e << ", reference " << r << '\n';
  EXPECT_GT(r, 0.0);
  EXPECT_NEAR(e / r, 1.0, 0.02);
}

// The bounce off an object (docs/dominant-lights.md, "Bounce light of the suns"): the ground in
// front of a sphere resting on it, which a 30 degree sun behind the camera lights, also gets the
// light the sphere's sunlit face bounces onto it. The bake's sun bounce against a reference with
// every bounce: 0.2% apart; the transfer's estimate without it was 6% too dark.
TEST_F(ShadowTest, SunlitObjectLightsTheGroundBesideIt) {
  const nlohmann::json sphere = {{{"shape", "sphere"}, {"translation", {0.0, 0.5, 0.0}}, {"scale", 0.5},
                                  {"material", {{"baseColor", {0.5, 0.5, 0.5}}, {"metallic", 0.0}, {"roughness", 1.0}, {"specular", 0.0}}}}};
  const SunScene s = writeSunScene("object_bounce", sunDirection(0.0f, 30.0f), 0.5f, sphere);
  const BakedScene bake = bakeWithSun(s);
  Renderer renderer(bake);
  const Image engine = renderEngine(renderer, bake, ShadingMode::LightsShadowed);
  const Image reference = renderTrace(s, 8);
  const glm::vec2 p = project(bake, glm::vec3(0.0f, 0.0f, 0.62f));
  const double e = meanLuminanceAround(engine, p, 2, 1), r = meanLuminanceAround(reference, p, 2, 1);
  std::cout << "ground in front of the sphere: engine " << e << ", reference " << r << '\n';
  EXPECT_GT(r, 0.0);
  EXPECT_NEAR(e / r, 1.0, 0.02);
}

// The bake's sun bounce is read only for the lights it was baked for (bakedSunBounceFor): the same
// suns in the same directions, as many or fewer drawn. Otherwise (another environment, an extra
// rotation, a bake without it) the engine estimates the bounce from the transfer, and the ground
// in front of the sunlit sphere of the test above comes out differently.
TEST_F(ShadowTest, TheBakedSunBounceStandsOnlyForTheSunsItWasBakedFor) {
  const glm::vec3 a = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), b = glm::normalize(glm::vec3(-0.6f, 0.5f, 0.2f));
  EnvironmentLight sunA, sunB;
  sunA.direction = a;
  sunB.direction = b;
  EXPECT_TRUE(bakedSunBounceFor({a, b}, {sunA, sunB}));
  EXPECT_TRUE(bakedSunBounceFor({a, b}, {sunA}));
  EXPECT_TRUE(bakedSunBounceFor({a}, {}));
  EXPECT_FALSE(bakedSunBounceFor({}, {sunA}));
  EXPECT_FALSE(bakedSunBounceFor({a}, {sunA, sunB}));
  EXPECT_FALSE(bakedSunBounceFor({b, a}, {sunA, sunB}));
  EnvironmentLight turned = sunA;
  turned.direction = glm::normalize(a + glm::vec3(1e-4f, 0.0f, 0.0f));
  EXPECT_FALSE(bakedSunBounceFor({a}, {turned}));

  const nlohmann::json sphere = {{{"shape", "sphere"}, {"translation", {0.0, 0.5, 0.0}}, {"scale", 0.5},
                                  {"material", {{"baseColor", {0.5, 0.5, 0.5}}, {"metallic", 0.0}, {"roughness", 1.0}, {"specular", 0.0}}}}};
  const SunScene s = writeSunScene("baked_bounce", sunDirection(0.0f, 30.0f), 0.5f, sphere);
  const BakedScene baked = bakeWithSun(s);
  for (const Mesh& mesh : baked.scene.meshes) ASSERT_EQ(mesh.attributes.count(kSunBounceAttribute), 1u) << mesh.name;
  BakedScene estimated = baked;
  for (Mesh& mesh : estimated.scene.meshes) mesh.attributes.erase(kSunBounceAttribute);
  Renderer bakedRenderer(baked), estimatedRenderer(estimated);
  const glm::vec2 p = project(baked, glm::vec3(0.0f, 0.0f, 0.62f));
  const double withBake = meanLuminanceAround(renderEngine(bakedRenderer, baked, ShadingMode::LightsShadowed), p, 2, 1);
  const double without = meanLuminanceAround(renderEngine(estimatedRenderer, estimated, ShadingMode::LightsShadowed), p, 2, 1);
  std::cout << "ground in front of the sphere: baked bounce " << withBake << ", estimated " << without << '\n';
  EXPECT_GT(withBake / without, 1.03);
}

}  // namespace
}  // namespace iblkit
