#include "raytrace/alpha_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "raytrace/ray_scene.h"
#include "support/generated_textures.h"

namespace iblkit {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
const RayQuery kCamera{RayKind::Camera, {}};

// A scene of quads (tests/support/generated_textures.h) traced through an AlphaFilter.
struct FilteredScene {
  Scene scene;
  std::shared_ptr<AlphaFilter> filter;
  RayScene rays{std::string()};

  void build(bool cameraRays = true) {
    std::vector<const Mesh*> meshes;
    for (const Mesh& mesh : scene.meshes) {
      rays.addTriangleMesh(mesh.positions, mesh.indices);
      meshes.push_back(&mesh);
    }
    filter = std::make_shared<AlphaFilter>(
        meshes, scene.materials,
        std::make_shared<SceneTextures>(scene.textures, scene.images, scene.materials), kAllTextureSlots,
        cameraRays);
    rays.setAlphaFilter(filter);
    rays.commit();
  }
};

Material maskMaterial(float cutoff) {
  Material material;
  material.alphaMode = AlphaMode::Mask;
  material.alphaCutoff = cutoff;
  material.doubleSided = true;
  return material;
}

// An 8 x 1 strip of alphas 0, 36, ..., 252 over the unit quad, MASK at alpha 128 / 255.
FilteredScene maskedStrip() {
  FilteredScene s;
  s.scene.materials = {maskMaterial(128.0f / 255.0f)};
  s.scene.materials[0].baseColorTexture = test::addTexture(
      s.scene, test::generatedImage(8, 1, [](int x, int) { return glm::u8vec4(255, 255, 255, 36 * x); }));
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  s.scene.meshes[0].tangents.clear();
  s.build();
  return s;
}

// MASK is exact for shadow rays and closest-hit rays alike: a ray through texel x is blocked
// exactly when 36 x >= 128, i.e. from texel 4 on, at every point of the texel.
TEST(AlphaFilter, MaskIsExactForOcclusionAndClosestHit) {
  FilteredScene s = maskedStrip();
  ASSERT_EQ(s.filter->needs(0), unsigned(AlphaFilter::kAlphaTest));
  for (int x = 0; x < 8; ++x)
    for (float within : {0.05f, 0.5f, 0.95f}) {
      const glm::vec3 origin((x + within) / 8.0f, 0.3f, 1.0f), down(0.0f, 0.0f, -1.0f);
      const bool present = 36 * x >= 128;
      EXPECT_EQ(s.rays.occluded(origin, down, 0.0f, kInfinity), present) << "texel " << x;
      EXPECT_EQ(s.rays.intersect({origin, down}, 0.0f, kInfinity).hit, present) << "texel " << x;
      EXPECT_EQ(s.rays.intersect({origin, down}, 0.0f, kInfinity, kCamera).hit, present) << "texel " << x;
    }
}

// The batch form of occluded gives each shadow ray its own query: through a BLEND strip of alphas
// 0 .. 252, a ray with a wide cone reads a coarse level of the alpha (about their mean), a ray with
// none the finest, so the rays through the clear texels are blocked only with the wide cone;
// interleaved in one batch, each ray gets what it gets alone.
TEST(AlphaFilter, BatchedShadowRaysEachSeeTheirOwnCone) {
  FilteredScene s;
  Material blend;
  blend.alphaMode = AlphaMode::Blend;
  blend.doubleSided = true;
  s.scene.materials = {blend};
  s.scene.materials[0].baseColorTexture = test::addTexture(
      s.scene, test::generatedImage(8, 1, [](int x, int) { return glm::u8vec4(255, 255, 255, 36 * x); }),
      TextureSampler{});  // trilinear: the cone picks the level
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  s.scene.meshes[0].tangents.clear();
  s.build();
  ASSERT_EQ(s.filter->needs(0), unsigned(AlphaFilter::kAlphaTest));
  std::vector<OcclusionQuery> rays;
  std::vector<std::uint8_t> alone;
  for (int i = 0; i < 64; ++i)
    for (const float width : {0.0f, 4.0f}) {
      const RayQuery query{RayKind::Secondary, RayCone{width, 0.0f, {}}};
      rays.push_back({glm::vec3((i + 0.5f) / 64.0f, 0.3f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f), 0.0f, kInfinity, query});
      alone.push_back(s.rays.occluded(rays.back().origin, rays.back().direction, 0.0f, kInfinity, query));
    }
  int onlyWide = 0;
  for (std::size_t k = 0; k < alone.size(); k += 2) onlyWide += !alone[k] && alone[k + 1];
  ASSERT_GT(onlyWide, 2) << "the cone must matter for this test to see the queries";
  std::vector<std::uint8_t> batched(rays.size(), 2);
  s.rays.occluded(rays, batched);
  EXPECT_EQ(batched, alone);
}

// An alpha exactly at the cutoff is there (glTF: "rendered fully opaque if alpha >= cutoff").
TEST(AlphaFilter, AlphaAtTheCutoffIsThere) {
  FilteredScene s;
  s.scene.materials = {maskMaterial(0.5f)};
  s.scene.materials[0].alpha = 0.5f;
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  s.build();
  EXPECT_EQ(s.filter->needs(0), 0u) << "a constant alpha that passes needs no test";
  EXPECT_TRUE(s.rays.occluded({0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInfinity));
  s = FilteredScene{};
  s.scene.materials = {maskMaterial(0.5f)};
  s.scene.materials[0].alpha = 0.49f;
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  s.build();
  EXPECT_FALSE(s.rays.occluded({0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInfinity));
}

// A masked card in front of an opaque one: the closest hit skips the masked texels and finds the
// card behind (the filter rejects a candidate, Embree goes on).
TEST(AlphaFilter, ClosestHitGoesOnBehindAMaskedTexel) {
  FilteredScene s;
  s.scene.materials = {maskMaterial(128.0f / 255.0f), Material{}};
  s.scene.materials[0].baseColorTexture = test::addTexture(
      s.scene, test::generatedImage(8, 1, [](int x, int) { return glm::u8vec4(255, 255, 255, 36 * x); }));
  s.scene.materials[1].doubleSided = true;
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0), test::texturedQuad(-1.0f, 2.0f, -1.0f, 1)};
  s.build();
  EXPECT_EQ(s.filter->needs(1), 0u);
  const Hit through = s.rays.intersect({{0.5f / 8.0f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
  ASSERT_TRUE(through.hit);
  EXPECT_EQ(through.geomId, 1u);
  EXPECT_FLOAT_EQ(through.t, 2.0f);
  const Hit stopped = s.rays.intersect({{7.5f / 8.0f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
  EXPECT_EQ(stopped.geomId, 0u);
}

// A base colour texture whose alpha is 255 everywhere (an RGB image) filters to exactly 1, so the
// factor alone decides, with no test: BLEND alpha 1 is there for every ray; one texel of alpha
// 254 brings the test back.
TEST(AlphaFilter, AnOpaqueTextureLeavesTheFactorToDecide) {
  for (int lowered : {0, 1}) {
    FilteredScene s;
    Material blend;
    blend.alphaMode = AlphaMode::Blend;
    blend.doubleSided = true;
    s.scene.materials = {blend};
    s.scene.materials[0].baseColorTexture =
        test::addTexture(s.scene, test::generatedImage(8, 8, [&](int x, int y) {
                           return glm::u8vec4(30 * x, 30 * y, 90, x == 3 && y == 5 && lowered ? 254 : 255);
                         }));
    s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
    s.build();
    EXPECT_EQ(s.filter->needs(0), lowered ? unsigned(AlphaFilter::kAlphaTest) : 0u);
    for (float x : {0.1f, 0.45f, 0.8f})
      EXPECT_TRUE(s.rays.occluded({x, 0.3f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInfinity));
  }
}

// BLEND alpha 0.5: about half of many random rays are blocked; each ray decides the same way
// in intersect and occluded, and again when traced again.
TEST(AlphaFilter, BlendCoverageBlocksAboutAlphaAndIsDeterministic) {
  FilteredScene s;
  Material blend;
  blend.alphaMode = AlphaMode::Blend;
  blend.alpha = 0.5f;
  blend.doubleSided = true;
  s.scene.materials = {blend};
  s.scene.meshes = {test::texturedQuad(-10.0f, 10.0f, 0.0f, 0)};
  s.build();
  ASSERT_EQ(s.filter->needs(0), unsigned(AlphaFilter::kAlphaTest));
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const int n = 4000;
  int blocked = 0;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 origin(uniform(random), uniform(random), 1.0f);
    const glm::vec3 direction = glm::normalize(glm::vec3(uniform(random), uniform(random), -2.0f));
    const bool occluded = s.rays.occluded(origin, direction, 0.0f, kInfinity);
    EXPECT_EQ(s.rays.intersect({origin, direction}, 0.0f, kInfinity).hit, occluded);
    EXPECT_EQ(s.rays.occluded(origin, direction, 0.0f, kInfinity), occluded);
    blocked += occluded;
  }
  // Binomial(4000, 0.5): standard deviation sqrt(1000) ~ 32 rays; 5 sigma.
  EXPECT_NEAR(blocked, n / 2, 160);
}

// doubleSided false: camera rays pass through the back face, every other ray hits it; the
// front face is there for all. doubleSided true: both faces for all.
TEST(AlphaFilter, SingleSidedBackFacesAreCulledForCameraRaysOnly) {
  for (bool doubleSided : {false, true}) {
    FilteredScene s;
    s.scene.materials = {Material{}};
    s.scene.materials[0].doubleSided = doubleSided;
    s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
    s.build();
    EXPECT_EQ(s.filter->needs(0), doubleSided ? 0u : unsigned(AlphaFilter::kCullCameraBackFaces));
    const Ray front{{0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, back{{0.5f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}};
    EXPECT_TRUE(s.rays.intersect(front, 0.0f, kInfinity, kCamera).hit);
    EXPECT_EQ(s.rays.intersect(back, 0.0f, kInfinity, kCamera).hit, doubleSided);
    EXPECT_TRUE(s.rays.intersect(back, 0.0f, kInfinity).hit);
    EXPECT_TRUE(s.rays.occluded(back.origin, back.direction, 0.0f, kInfinity, kCamera));
  }
  // The baker traces no camera rays: no callback for single-sided geometry.
  FilteredScene baker;
  baker.scene.materials = {Material{}};
  baker.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  baker.build(/*cameraRays=*/false);
  EXPECT_EQ(baker.filter->needs(0), 0u);
}

// Embree called directly on the scene (the replay benchmark) through a RayQueryContext runs the
// same callbacks with the same query: a camera ray passes through the back face, another does not.
TEST(AlphaFilter, DirectEmbreeQueriesThroughARayQueryContextSeeTheQuery) {
  FilteredScene s;
  s.scene.materials = {Material{}};
  s.scene.meshes = {test::texturedQuad(0.0f, 1.0f, 0.0f, 0)};
  s.build();
  ASSERT_EQ(s.filter->needs(0), unsigned(AlphaFilter::kCullCameraBackFaces));
  for (const RayKind kind : {RayKind::Camera, RayKind::Secondary}) {
    const RayQuery query{kind, {}};
    RayQueryContext context(query);
    RTCRayHit ray{};
    ray.ray.org_x = 0.5f, ray.ray.org_y = 0.5f, ray.ray.org_z = -1.0f;
    ray.ray.dir_z = 1.0f;
    ray.ray.tfar = kInfinity;
    ray.ray.mask = ~0u;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s.rays.embreeScene(), &context.context, &ray);
    EXPECT_EQ(ray.hit.geomID != RTC_INVALID_GEOMETRY_ID, kind == RayKind::Secondary);
  }
}

// The footprint: width sqrt(uv area / world area) / cosine, the cosine clamped at 1 / 16.
TEST(AlphaFilter, TextureFootprintOfARayCone) {
  Mesh quad = test::texturedQuad(0.0f, 2.0f, 0.0f, 0);  // uv [0, 1]^2 over 2 x 2 metres
  EXPECT_FLOAT_EQ(uvPerWorldArea(quad, 0, 0), 0.25f);
  EXPECT_FLOAT_EQ(uvPerWorldArea(quad, 1, 1), 0.0f) << "no TEXCOORD_1";
  EXPECT_FLOAT_EQ(textureFootprint(0.1f, 0.25f, 1.0f), 0.05f);
  EXPECT_FLOAT_EQ(textureFootprint(0.1f, 0.25f, -0.5f), 0.1f);
  EXPECT_FLOAT_EQ(textureFootprint(0.1f, 0.25f, 0.001f), 0.05f * kMaxTextureAnisotropy);
  EXPECT_FLOAT_EQ((RayCone{0.5f, 0.01f, {}}.widthAt(10.0f)), 0.6f);
}

TEST(AlphaFilter, RefusesATableOfTheWrongSize) {
  RayScene rays;
  const Mesh quad = test::texturedQuad(0.0f, 1.0f, 0.0f, 0);
  rays.addTriangleMesh(quad.positions, quad.indices);
  const std::vector<Material> materials = {Material{}};
  EXPECT_THROW(
      rays.setAlphaFilter(std::make_shared<AlphaFilter>(std::vector<const Mesh*>{}, materials, nullptr)),
      Error);
}

}  // namespace
}  // namespace iblkit
