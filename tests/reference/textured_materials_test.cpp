// The reference tracer with textured glTF materials: alpha (MASK holes, BLEND coverage),
// doubleSided, base colour, normal and emissive textures read at the hit, and the ray-cone
// footprint. Real Embree, textures generated in code (tests/support/generated_textures.h).
#include <gtest/gtest.h>

#include <cmath>

#include "raytrace/alpha_filter.h"
#include "reference/renderer.h"
#include "reference/test_scenes.h"
#include "support/generated_textures.h"

namespace iblkit {
namespace {

constexpr int kSize = 16;
const glm::vec3 kSky(0.25f, 0.5f, 1.0f);

// A black Lambert surface: it reflects nothing, so every pixel is the environment or 0.
Material black() {
  Material material = test::lambert(0.0f);
  material.doubleSided = true;
  return material;
}

// The quad [-1, 1]^2 at z = 0 seen head-on from z = 3 (or -3) with a field of view it fills
// exactly: pixel (i, j) of a kSize image sees quad uv ((i + 0.5) / kSize, (j + 0.5) / kSize).
Scene quadScene(const Material& material, float cameraZ = 3.0f) {
  Scene scene;
  scene.materials = {material};
  scene.meshes = {test::texturedQuad(-1.0f, 1.0f, 0.0f, 0)};
  scene.bounds = objectBounds(scene.meshes);
  scene.camera = Camera::lookAt(glm::vec3(0.0f, 0.0f, cameraZ), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                2.0f * std::atan(1.0f / 3.0f), 0.1f, 100.0f);
  return scene;
}

RenderResult renderPath(Scene scene, const glm::vec3& sky, int spp = 16, unsigned slots = kAllTextureSlots) {
  const Camera camera = sceneCamera(scene, 1.0f);
  const RenderScene renderScene(std::move(scene), slots);
  const EnvironmentMap environment = EnvironmentMap::constant(sky);
  const EnvironmentSampler sampler(environment);
  const Integrator integrator(renderScene, environment, sampler, test::integratorOf(IntegratorKind::Path));
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.samplesPerPixel = spp;
  settings.seed = 3;
  settings.threads = 2;
  return render(integrator, camera, settings);
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance, const std::string& where) {
  EXPECT_NEAR(actual.r, expected.r, tolerance) << where;
  EXPECT_NEAR(actual.g, expected.g, tolerance) << where;
  EXPECT_NEAR(actual.b, expected.b, tolerance) << where;
}

// A 4 x 4 alpha texture whose centre 2 x 2 texels are 0 (the hole), MASK at 0.5: pixels through
// the hole are exactly the environment, pixels on the card exactly black.
TEST(TexturedMaterials, MaskedHoleShowsTheEnvironment) {
  Material material = black();
  material.alphaMode = AlphaMode::Mask;
  Scene scene = quadScene(material);
  scene.materials[0].baseColorTexture = test::addTexture(scene, test::generatedImage(4, 4, [](int x, int y) {
    const bool hole = (x == 1 || x == 2) && (y == 1 || y == 2);
    return glm::u8vec4(255, 255, 255, hole ? 0 : 255);
  }));
  const RenderResult r = renderPath(std::move(scene), kSky);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      if (i % 4 == 0 || i % 4 == 3 || j % 4 == 0 || j % 4 == 3) continue;  // pixels astride a texel edge
      const bool hole = (i / 4 == 1 || i / 4 == 2) && (j / 4 == 1 || j / 4 == 2);
      const std::string where = "pixel " + std::to_string(i) + ", " + std::to_string(j);
      expectNear(glm::vec3(r.beauty.at(i, j)), hole ? kSky : glm::vec3(0.0f), 1e-6f, where);
      EXPECT_EQ(r.mask.at(i, j).r, hole ? 0.0f : 1.0f) << where;
    }
}

// BLEND alpha 0.5 is coverage: the black card in front of the sky transmits about half of it.
TEST(TexturedMaterials, BlendHalfAlphaCardTransmitsAboutHalf) {
  Material material = black();
  material.alphaMode = AlphaMode::Blend;
  material.alpha = 0.5f;
  const RenderResult r = renderPath(quadScene(material), glm::vec3(1.0f), 64);
  double sum = 0.0;
  for (const glm::vec4& pixel : r.beauty.pixels()) sum += pixel.g;
  // 16384 camera rays, each through with probability 1/2: standard deviation 0.004.
  EXPECT_NEAR(sum / double(kSize * kSize), 0.5, 0.02);
}

// A single-sided quad seen from behind is not there for camera rays (the raster culls it): the
// image is the environment. Double-sided, it hides the environment.
TEST(TexturedMaterials, SingleSidedQuadSeenFromBehindIsInvisible) {
  Material material = black();
  material.doubleSided = false;
  const RenderResult back = renderPath(quadScene(material, -3.0f), kSky, 4);
  for (const glm::vec4& pixel : back.beauty.pixels()) expectNear(glm::vec3(pixel), kSky, 1e-6f, "behind");
  const RenderResult front = renderPath(quadScene(material, 3.0f), kSky, 4);
  expectNear(glm::vec3(front.beauty.at(8, 8)), glm::vec3(0.0f), 1e-6f, "in front");
  material.doubleSided = true;
  const RenderResult both = renderPath(quadScene(material, -3.0f), kSky, 4);
  expectNear(glm::vec3(both.beauty.at(8, 8)), glm::vec3(0.0f), 1e-6f, "double-sided, behind");
}

// A 4 x 4 checker of sRGB 255 and 64 times the factor 0.5: the albedo layer is the decoded
// texture times the factor, texel by texel; with the slots off it is the factor.
TEST(TexturedMaterials, CheckerBaseColourAlbedoMatchesTheTexture) {
  Material material = test::lambert(0.5f);
  material.doubleSided = true;
  Scene scene = quadScene(material);
  scene.materials[0].baseColorTexture = test::addTexture(scene, test::generatedImage(4, 4, [](int x, int y) {
    const std::uint8_t v = (x + y) % 2 ? 255 : 64;
    return glm::u8vec4(v, v, v, 255);
  }));
  const Scene untextured = scene;
  const RenderResult r = renderPath(std::move(scene), kSky, 4);
  const float dark = 0.5f * srgbToLinear(64);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      if (i % 4 == 0 || i % 4 == 3 || j % 4 == 0 || j % 4 == 3) continue;  // pixels at a texel edge
      const float expected = (i / 4 + j / 4) % 2 ? 0.5f : dark;
      EXPECT_NEAR(r.albedo.at(i, j).g, expected, 1e-6f) << "pixel " << i << ", " << j;
    }
  const RenderResult off = renderPath(untextured, kSky, 4, 0u);
  EXPECT_NEAR(off.albedo.at(5, 1).g, 0.5f, 1e-6f);
  EXPECT_NEAR(off.albedo.at(1, 1).g, 0.5f, 1e-6f);
}

// A constant normal map texel n_t on the quad (tangent +x, w = 1 or -1): the normal layer is
// normalize(s n_t.x T + s n_t.y w (N x T) + n_t.z N) with s the normal scale, computed by hand.
TEST(TexturedMaterials, NormalMappedPlaneNormalMatchesTheAnalyticNormal) {
  for (float handedness : {1.0f, -1.0f}) {
    Material material = test::lambert(0.5f);
    material.doubleSided = true;
    material.normalScale = 0.8f;
    Scene scene = quadScene(material);
    for (glm::vec4& t : scene.meshes[0].tangents) t.w = handedness;
    scene.materials[0].normalTexture =
        test::addTexture(scene, test::generatedImage(2, 2, [](int, int) { return glm::u8vec4(200, 90, 230, 255); }));
    const RenderResult r = renderPath(std::move(scene), kSky, 4);
    const glm::vec3 local = glm::vec3(2.0f * 200.0f / 255.0f - 1.0f, 2.0f * 90.0f / 255.0f - 1.0f,
                                      2.0f * 230.0f / 255.0f - 1.0f) *
                            glm::vec3(0.8f, 0.8f, 1.0f);
    const glm::vec3 expected = glm::normalize(glm::vec3(local.x, handedness * local.y, local.z));
    for (int p : {2, 8, 13})
      expectNear(glm::vec3(r.normal.at(p, p)), expected, 1e-5f, "pixel " + std::to_string(p));
  }
}

// An emissive texture (sRGB) times emissiveFactor shows in the beauty under a black sky.
TEST(TexturedMaterials, EmissiveTextureTimesFactor) {
  Material material = black();
  material.emissive = glm::vec3(2.0f);
  Scene scene = quadScene(material);
  scene.materials[0].emissiveTexture = test::addTexture(scene, test::generatedImage(2, 1, [](int x, int) {
    return x == 0 ? glm::u8vec4(188, 0, 255, 255) : glm::u8vec4(0, 0, 0, 255);
  }));
  const RenderResult r = renderPath(std::move(scene), glm::vec3(0.0f), 4);
  expectNear(glm::vec3(r.beauty.at(3, 8)), glm::vec3(2.0f * srgbToLinear(188), 0.0f, 2.0f), 1e-5f, "left");
  expectNear(glm::vec3(r.beauty.at(12, 8)), glm::vec3(0.0f), 1e-6f, "right");
}

// The footprint picks the mip level: a 2 x 2 checker of sRGB 255 and 0 (trilinear, mip-mapped)
// reads its texel at the finest level and the linear mean 0.5 (the 1 x 1 level) once the cone is
// wider than the texture.
TEST(TexturedMaterials, RayConeWidthSelectsTheMipLevel) {
  Material material = test::lambert(1.0f);
  material.doubleSided = true;
  Scene scene = quadScene(material);
  TextureSampler trilinear;  // LINEAR, LINEAR_MIPMAP_LINEAR, repeat
  scene.materials[0].baseColorTexture = test::addTexture(scene,
                                                         test::generatedImage(2, 2, [](int x, int y) {
                                                           const std::uint8_t v = (x + y) % 2 ? 255 : 0;
                                                           return glm::u8vec4(v, v, v, 255);
                                                         }),
                                                         trilinear);
  const RenderScene renderScene(std::move(scene));
  const Ray ray{{-0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}};  // the centre of texel (0, 0), sRGB 0
  const Hit hit = renderScene.rays().intersect(ray, 0.0f, std::numeric_limits<float>::infinity());
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(renderScene.surfacePoint(hit, -ray.direction).baseColor.g, 0.0f, 1e-6f);
  // uv per metre 1/2: a cone 8 m wide at the hit is 4 uv wide, lod log2(4 * 2) = 3 >= the 1 x 1 level.
  EXPECT_NEAR(renderScene.surfacePoint(hit, -ray.direction, RayCone{8.0f, 0.0f, {}}).baseColor.g, 0.5f,
              0.01f);
  EXPECT_NEAR(renderScene.surfacePoint(hit, -ray.direction, RayCone{0.0f, 8.0f / 3.0f, {}}).baseColor.g, 0.5f,
              0.01f);
}

// A MASK grate of 1-texel alpha checks (64 x 64 over a 4 m square, 0.2 m above a white Lambert
// receiver), seen only through the receiver's direct light: the light strategy's shadow rays and
// the BRDF strategy's rays must meet the same grate, so the two estimates converge to one image.
// Fails when a bounce widens the cone by the sampled lobe's width (a Lambert lobe: about 1 radian),
// which made the BRDF rays read the checks' coarse mip levels (alpha 0.5: opaque at cutoff 0.5)
// while the shadow rays saw the holes.
TEST(TexturedMaterials, EveryStrategySeesTheSameMaskedGrate) {
  Scene scene;
  Material receiver = test::lambert(1.0f);
  Material grate = black();
  grate.alphaMode = AlphaMode::Mask;
  scene.materials = {receiver, grate};
  scene.meshes = {test::texturedQuad(-2.0f, 2.0f, 0.0f, 0), test::texturedQuad(-2.0f, 2.0f, 0.2f, 1)};
  TextureSampler trilinear;  // LINEAR, LINEAR_MIPMAP_LINEAR, repeat: the coarse levels hold alpha 0.5
  scene.materials[1].baseColorTexture = test::addTexture(scene,
                                                         test::generatedImage(64, 64, [](int x, int y) {
                                                           return glm::u8vec4(255, 255, 255, (x + y) % 2 ? 255 : 0);
                                                         }),
                                                         trilinear);
  scene.bounds = objectBounds(scene.meshes);
  scene.camera = Camera::lookAt(glm::vec3(0.0f, 0.0f, 0.1f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                glm::radians(60.0f), 0.01f, 100.0f);
  const EnvironmentMap environment = EnvironmentMap::constant(glm::vec3(1.0f));
  double mean[2] = {0.0, 0.0};
  const EnvSampling strategies[2] = {EnvSampling::Env, EnvSampling::Brdf};
  for (int s = 0; s < 2; ++s) {
    const RenderResult r = test::renderWith(scene, environment, test::integratorOf(IntegratorKind::Direct, strategies[s]),
                                            kSize, 256, 5);
    for (const glm::vec4& pixel : r.beauty.pixels()) mean[s] += pixel.g / double(kSize * kSize);
  }
  // The grate spans nearly the whole sky and half of it is open: about 0.5 of the unoccluded 1
  // (0.47 measured). 65,536 samples of each strategy: standard errors below 0.003.
  EXPECT_GT(mean[0], 0.4);
  EXPECT_LT(mean[0], 0.9);
  EXPECT_NEAR(mean[1], mean[0], 0.02) << "light strategy " << mean[0] << ", BRDF strategy " << mean[1];
}

// The camera cone: spread = footprint x the pixel's angle 2 tan(fov / 2) / height.
TEST(TexturedMaterials, CameraRayConeIsAFractionOfThePixel) {
  const Camera camera = Camera::lookAt(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                       2.0f * std::atan(1.0f / 3.0f), 0.1f, 100.0f);
  const RayCone cone = cameraRayCone(camera, 16, 0.5f);
  EXPECT_FLOAT_EQ(cone.width, 0.0f);
  EXPECT_NEAR(cone.spread, 0.5f * 2.0f / 3.0f / 16.0f, 1e-7f);
}

// The camera ray's differentials give the raster's footprint: the longer of the uv steps between
// rays `footprint` pixels apart along x and along y (what GL's dFdx and dFdy of the uv measure, OpenGL
// 4.5 eq. 8.7), here by finite differences of exact plane hits, on a triangle seen at 75 degrees
// whose uv stretches u three times as much as v. The ray cone's isotropic footprint, sqrt of the uv
// area ratio over the cosine, is not that (it is checked to differ by more than a fifth).
TEST(TexturedMaterials, CameraDifferentialsGiveTheUvStepsBetweenNeighbouringRays) {
  const Camera camera = Camera::lookAt(glm::vec3(0.3f, 1.2f, 3.0f), glm::vec3(0.0f),
                                       glm::vec3(0.0f, 1.0f, 0.0f), glm::radians(40.0f), 0.1f, 100.0f);
  constexpr int kWidth = 96, kHeight = 64;
  const float footprint = 0.5f;
  const RayCone cone = cameraRayCone(camera, kHeight, footprint);
  ASSERT_TRUE(cone.pixel.present());
  // A plane through the origin, its normal 75 degrees from the view direction.
  const glm::vec3 normal = glm::normalize(glm::vec3(0.0f, 0.26f, 1.0f) - 0.9f * camera.forward);
  const glm::vec3 e1 = glm::normalize(glm::cross(normal, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 e2 = glm::cross(normal, e1);
  Mesh mesh;
  mesh.positions = {-4.0f * e1 - 4.0f * e2, 4.0f * e1 - 4.0f * e2, 4.0f * e2};
  const auto uvOf = [&](const glm::vec3& p) { return glm::vec2(3.0f * glm::dot(p, e1), glm::dot(p, e2)); };
  for (const glm::vec3& p : mesh.positions) mesh.texcoords.push_back(uvOf(p));
  mesh.indices = {0, 1, 2};
  const PrimaryRays rays(camera, kWidth, kHeight);
  const auto hitUv = [&](glm::vec2 raster, float* t = nullptr) {
    const Ray ray = rays(raster);
    const float distance = -glm::dot(ray.origin, normal) / glm::dot(ray.direction, normal);
    if (t) *t = distance;
    return uvOf(ray.origin + distance * ray.direction);
  };
  int checked = 0;
  float coneRatio = 1.0f;
  for (glm::vec2 raster : {glm::vec2(48.0f, 32.0f), glm::vec2(10.0f, 50.0f), glm::vec2(80.0f, 12.0f)}) {
    float t = 0.0f;
    const glm::vec2 uv = hitUv(raster, &t);
    const float dx = glm::length(hitUv(raster + glm::vec2(footprint, 0.0f)) - uv);
    const float dy = glm::length(hitUv(raster + glm::vec2(0.0f, footprint)) - uv);
    const Ray ray = rays(raster);
    const float differential =
        textureFootprintFromDifferentials(cone.pixel, ray.direction, t, normal, uvGradient(mesh, 0, 0));
    EXPECT_NEAR(differential, std::max(dx, dy), 0.01f * std::max(dx, dy)) << raster.x << ", " << raster.y;
    const float coneFootprint =
        textureFootprint(cone.widthAt(t), uvPerWorldArea(mesh, 0, 0), glm::dot(ray.direction, normal));
    coneRatio = std::min(coneRatio, std::abs(coneFootprint / differential - 1.0f));
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  EXPECT_GT(coneRatio, 0.2f);
  // No such uv set: 0 (the sharpest level), as for a cone.
  EXPECT_EQ(textureFootprintFromDifferentials(cone.pixel, camera.forward, 3.0f, normal, uvGradient(mesh, 0, 1)),
            0.0f);
  // A ray in the plane: the coarsest level, not a NaN.
  EXPECT_EQ(textureFootprintFromDifferentials(cone.pixel, e1, 3.0f, normal, uvGradient(mesh, 0, 0)),
            std::numeric_limits<float>::max());
  // The gradient itself: u = 3 e1 . p and v = e2 . p on this plane.
  const UvGradient gradient = uvGradient(mesh, 0, 0);
  EXPECT_LT(glm::length(gradient.du - 3.0f * e1), 1e-5f);
  EXPECT_LT(glm::length(gradient.dv - e2), 1e-5f);
}

}  // namespace
}  // namespace iblkit
