// The raster (iblkit-view through EGL) against the reference (iblkit-trace, Embree) on textured
// glTF materials (issue 14, "Raster against reference"): the real programs on small generated
// scenes, the engine at the report's settings (report/report_settings.h, passed as
// report/stage_commands.cpp does: --samples 4 --sample-shading --supersample 2) and the tracer at
// its matching footprint (--texture-footprint 0.5, docs/reference-tracer.md "Texture filtering").
// Each case isolates what it compares: a lighting for which the engine mode is exact, so only the
// texture path (decoding, filtering, tangent frames, perturbation, alpha) can differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/scene.h"
#include "score/score_images.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::GltfBuilder;

constexpr float kPi = 3.14159265358979f;

// Report settings (report/report_settings.h: engineSamples 4, engineSupersample 2).
const std::string kReportEngineSettings = " --samples 4 --sample-shading --supersample 2";

std::string q(const fs::path& p) { return test::shellQuoted(p); }

void run(const std::string& program, const std::string& arguments) {
  std::string output;
  const std::string command = q(test::binDir() / program) + " " + arguments + " 2>&1";
  ASSERT_EQ(test::runCommand(command, &output), 0) << command << "\n" << output;
}

// iblkit-view of a scene file (baked in memory), headless, at the report's settings.
void view(const fs::path& scene, const fs::path& out, const std::string& mode, int w, int h,
          const std::string& extra = "", const std::string& sampling = kReportEngineSettings) {
  run("iblkit-view", q(scene) + " --headless -o " + q(out) + " --mode " + mode + " --width " + std::to_string(w) +
                         " --height " + std::to_string(h) + sampling + " --ao-rays 16 " + extra);
}

void trace(const fs::path& scene, const fs::path& out, int w, int h, int spp, const std::string& extra = "") {
  run("iblkit-trace", q(scene) + " -o " + q(out) + " --width " + std::to_string(w) + " --height " +
                          std::to_string(h) + " --spp " + std::to_string(spp) +
                          " --texture-footprint 0.5 --seed 1 " + extra);
}

// An equirectangular map of `radiance` (core/latlong.h's convention, one sample per texel).
void writeEnvironment(const fs::path& file, int width, const RadianceFunction& radiance) {
  writeExr(file, latLongFromRadiance(width, width / 2, 1, radiance),
           {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
}

// RGBA8 pixels, row 0 at the top (glTF uv v = 0).
std::vector<std::uint8_t> pixels(int size, const std::function<glm::u8vec4(int, int)>& texel) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::u8vec4 t = texel(x, y);
      for (int c = 0; c < 4; ++c) rgba[(static_cast<std::size_t>(y) * size + x) * 4 + c] = t[c];
    }
  return rgba;
}

// A material json with one PNG texture in `slot` ("baseColorTexture" or "normalTexture") on
// sampler 0 (trilinear, repeat: the glTF default filters written out).
void addTexturedMaterial(GltfBuilder& builder, const std::vector<std::uint8_t>& png, const std::string& slot,
                         const json& pbr, const json& extra = json::object()) {
  json& document = builder.document();
  builder.addImage(png, "image/png");
  document["samplers"] = {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}};
  document["textures"] = {{{"source", 0}, {"sampler", 0}}};
  json material = extra;
  material["pbrMetallicRoughness"] = pbr;
  if (slot == "baseColorTexture")
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  else
    material[slot] = {{"index", 0}};
  document["materials"] = {material};
}

// A UV sphere of radius 1 (u around +Y from +X, v = 0 at the north pole), exact normals.
void addSphere(GltfBuilder& builder, int rings, int segments) {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float v = static_cast<float>(i) / rings, u = static_cast<float>(j) / segments;
      const float theta = kPi * v, phi = 2.0f * kPi * u;
      const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      positions.push_back(p);
      normals.push_back(p);
      uvs.emplace_back(u, v);
    }
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
      const std::uint32_t corners[2][3] = {{a, b, a + 1}, {a + 1, b, b + 1}};
      for (int t = 0; t < 2; ++t)
        if (t == 0 ? i > 0 : i < rings - 1)
          for (std::uint32_t c : corners[t]) indices.push_back(c);
    }
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(positions)},
                              {"NORMAL", builder.addFloats(normals)},
                              {"TEXCOORD_0", builder.addFloats(uvs)}}},
                            {"indices", builder.addIndices(indices)},
                            {"material", 0}});
}

// scene.json: the model, the environment file, a camera.
fs::path writeScene(const fs::path& dir, const fs::path& model, const fs::path& environment, glm::vec3 position,
                    glm::vec3 target, float yfov) {
  const json scene = {{"models", {{{"file", model.filename().string()}}}},
                      {"environment", {{"file", environment.filename().string()}}},
                      {"camera",
                       {{"position", {position.x, position.y, position.z}},
                        {"target", {target.x, target.y, target.z}},
                        {"yfov", yfov}}}};
  const fs::path file = dir / "scene.json";
  std::ofstream(file) << scene.dump(2);
  return file;
}

// A tangent-space normal map of the height field a sin(2 pi k x / size) sin(2 pi k y / size)
// (tileable, smooth), encoded n * 0.5 + 0.5 in 8 bits. Image y runs down the image, and glTF's
// bitangent points up it (+v is down, the bitangent -dP/dv... glTF 2.0 section 3.9.3: green is
// +Y of the tangent frame, "up" in the image): so n = (-dh/dx, +dh/dy, 1) normalised.
std::vector<std::uint8_t> bumpNormalMap(int size, int k, float amplitude) {
  return pixels(size, [&](int x, int y) {
    const float w = 2.0f * kPi * k / size;
    const float fx = w * (x + 0.5f), fy = w * (y + 0.5f);
    const float dhdx = amplitude * w * std::cos(fx) * std::sin(fy);
    const float dhdy = amplitude * w * std::sin(fx) * std::cos(fy);
    const glm::vec3 n = glm::normalize(glm::vec3(-dhdx, dhdy, 1.0f));
    const auto byte = [](float c) { return static_cast<std::uint8_t>(std::lround((c * 0.5f + 0.5f) * 255.0f)); };
    return glm::u8vec4(byte(n.x), byte(n.y), byte(n.z), 255);
  });
}

ImageScores score(const fs::path& reference, const fs::path& test, std::span<const std::uint8_t> mask = {}) {
  ScoreOptions options;
  options.ssim = false;
  return scoreImages(readExr(reference), readExr(test), mask, options);
}

class TextureAgreement : public ::testing::Test {
 protected:
  fs::path dir = test::scratchDir();
};

// 1. A checker on a Lambert quad (metallic 0, KHR_materials_specular 0: no specular lobe in either
// program) under a constant environment: SH9 of a constant map is exact (only the DC term, which
// the baker's window keeps), so `sh` is albedo x L exactly and the reference (no occluder, no
// interreflection on a lone plane) is the same; only base colour decoding and filtering differ.
// The quad fills the frame head-on; its 64-texel checker of 4-texel squares is magnified (2.4
// output pixels per texel, level 0 on both sides), so the bilinear ramps are what is compared.
// llvmpipe (Mesa 22.3) filters any GL_TEXTURE_MAX_ANISOTROPY > 1 with its own elliptical filter,
// which blurs an isotropic, magnified footprint well beyond bilinear (mean FLIP 0.047 here, at
// every anisotropy from 2 to 16); GL's anisotropic filtering, on a conformant driver, is trilinear
// for an isotropic footprint. So the bound is checked at --anisotropy 1 and the default's number
// is printed (docs/material-model.md "Raster against reference").
TEST_F(TextureAgreement, CheckerQuadHeadOnFlipAtMost002) {
  const std::vector<std::uint8_t> checker = pixels(64, [](int x, int y) {
    return ((x / 4 + y / 4) % 2) ? glm::u8vec4(230, 140, 40, 255) : glm::u8vec4(30, 60, 200, 255);
  });
  GltfBuilder builder;
  builder.addQuadNode();
  addTexturedMaterial(builder, test::encodePng(64, 64, checker), "baseColorTexture",
                      {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}},
                      {{"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}});
  builder.document()["extensionsUsed"] = {"KHR_materials_specular"};
  builder.write(dir / "quad.glb", GltfBuilder::Storage::Glb);
  writeEnvironment(dir / "constant.exr", 64, [](const glm::vec3&) { return glm::vec3(1.0f); });
  const fs::path scene = writeScene(dir, dir / "quad.glb", dir / "constant.exr", {0, 0, 2}, {0, 0, 0}, 45.0f);
  ASSERT_NO_FATAL_FAILURE(trace(scene, dir / "reference.exr", 128, 128, 128, "--integrator direct"));
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "sh", 128, 128, "--anisotropy 1"));
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster_16.exr", "sh", 128, 128));
  const ImageScores scores = score(dir / "reference.exr", dir / "raster.exr");
  const ImageScores anisotropic = score(dir / "reference.exr", dir / "raster_16.exr");
  std::printf("checker quad head-on: mean FLIP %.4f, relMSE %.3g (anisotropy 16: %.4f, %.3g)\n", scores.meanFlip,
              scores.relMse, anisotropic.meanFlip, anisotropic.relMse);
  EXPECT_LE(scores.meanFlip, 0.02);
  // The texture is really there: the image is not one flat colour (a grey quad would agree too).
  const Image raster = readExr(dir / "raster.exr");
  const Image::Stats stats = raster.stats();
  EXPECT_GT(stats.max.b - stats.min.b, 0.4f);
}

// 2. A normal-mapped quad under a sunny map, `mirror` against the tracer's `path` on a perfect
// mirror material (metallic 1, roughness 0: a delta lobe, F0 = baseColor = 1 so Fresnel is 1).
// `mirror` is L_env(reflect(-v, n)) and the reference of a lone plane is exactly that (the
// reflected ray leaves the plane and sees only the sky), so the pixel is a function of the
// perturbed normal alone, with the sun's gradient magnifying any difference in it: a tilt of a
// degree moves the sun's reflection by two. A Lambert quad in `sh` would blur the normal through
// the cosine lobe and add SH9's truncation of the sun, which is not the texture path's error.
TEST_F(TextureAgreement, NormalMappedQuadUnderSunFlipAtMost002) {
  GltfBuilder builder;
  builder.addQuadNode();
  addTexturedMaterial(builder, test::encodePng(128, 128, bumpNormalMap(128, 4, 1.2f)), "normalTexture",
                      {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.0}});
  builder.write(dir / "quad.glb", GltfBuilder::Storage::Glb);
  // A blue sky brightening to the horizon, a dark ground, and a soft sun (Gaussian, 4 degrees)
  // 12 degrees above the horizon towards +z, behind the camera, where the quad reflects it.
  const glm::vec3 sun = glm::normalize(glm::vec3(0.0f, std::sin(0.21f), std::cos(0.21f)));
  writeEnvironment(dir / "sunny.exr", 512, [&](const glm::vec3& d) {
    const glm::vec3 sky = d.y > 0.0f ? glm::mix(glm::vec3(0.9f, 0.95f, 1.0f), glm::vec3(0.2f, 0.4f, 0.9f), d.y)
                                     : glm::vec3(0.15f, 0.12f, 0.1f);
    const float angle = std::acos(std::clamp(glm::dot(d, sun), -1.0f, 1.0f));
    const float width = 4.0f * kPi / 180.0f;
    return sky + glm::vec3(20.0f, 18.0f, 15.0f) * std::exp(-(angle * angle) / (width * width));
  });
  const fs::path scene = writeScene(dir, dir / "quad.glb", dir / "sunny.exr", {0, 0, 2}, {0, 0, 0}, 45.0f);
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "mirror", 128, 128));
  ASSERT_NO_FATAL_FAILURE(trace(scene, dir / "reference.exr", 128, 128, 64));
  const ImageScores scores = score(dir / "reference.exr", dir / "raster.exr");
  std::printf("normal-mapped mirror quad, sun: mean FLIP %.4f, relMSE %.3g\n", scores.meanFlip, scores.relMse);
  EXPECT_LE(scores.meanFlip, 0.02);
  // The normal map is really applied: the flat mirror would show a smooth image; this one's
  // reflections of the sun come and go across the quad, so its luminance swings widely.
  const Image raster = readExr(dir / "raster.exr");
  EXPECT_GT(raster.stats().maxLuminance, 5.0f * raster.stats().meanLuminance);
}

// 3. The normal layers on a normal-mapped sphere (generated tangents: the sphere has no TANGENT)
// at the report's settings for a textured scene (report_case.cpp: no --sample-shading, and
// --anisotropy 1) on every pixel wholly on the sphere in both frames (the raster's alpha and the
// tracer's --mask 1; an edge pixel's mean mixes in the ground's normal by its coverage, which the
// two programs sample differently): within 1 degree, the limb included. The tracer's layer is the
// first hit's shading normal averaged over its 64 samples, the raster's the mean of its 2 x 2
// shaded points (one per supersampled pixel). Two rules make that hold at the limb
// (docs/material-model.md "Normal layers at the limb"): the shading normal is turned towards the
// viewer continuously (shadingNormalFacingViewer; falling back to the geometric normal jumped by
// the whole perturbation, 5.8 degrees between 4 and 64 samples), and the tracer's first-hit
// footprint is GL's isotropic one from ray differentials (a ray cone's isotropic width read a level
// too coarse or fine where the sphere's uv is anisotropic: +0.5 degree of tilt at the limb). What
// is left is the raster's 4-point quadrature of a normal that turns 9 degrees per pixel at the
// limb: 0.89 degrees measured, 0.22 with 64 points on both sides and level 0 only.
TEST_F(TextureAgreement, NormalMappedSphereNormalLayersWithinOneDegree) {
  GltfBuilder builder;
  addSphere(builder, 48, 96);
  addTexturedMaterial(builder, test::encodePng(256, 256, bumpNormalMap(256, 6, 2.0f)), "normalTexture",
                      {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}});
  builder.write(dir / "sphere.glb", GltfBuilder::Storage::Glb);
  writeEnvironment(dir / "constant.exr", 64, [](const glm::vec3&) { return glm::vec3(1.0f); });
  const fs::path scene =
      writeScene(dir, dir / "sphere.glb", dir / "constant.exr", {0.0f, 0.8f, 3.0f}, {0, 0, 0}, 45.0f);
  constexpr int kSize = 128;
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "sh", kSize, kSize,
                               "--normal " + q(dir / "raster_n.exr"),
                               " --samples 4 --supersample 2 --anisotropy 1"));
  ASSERT_NO_FATAL_FAILURE(
      trace(scene, dir / "reference.exr", kSize, kSize, 64,
            "--integrator direct --normal " + q(dir / "reference_n.exr") + " --mask " + q(dir / "mask.exr")));
  const Image raster = readExr(dir / "raster.exr");
  const Image coverage = readExr(dir / "mask.exr");
  const Image rasterNormal = readExr(dir / "raster_n.exr", nullptr, 0, PixelRepair::Keep);
  const Image referenceNormal = readExr(dir / "reference_n.exr", nullptr, 0, PixelRepair::Keep);
  const Camera camera = sceneCamera(loadScene(scene), 1.0f);
  // Bands of the angle between the sphere's normal and the direction to the camera.
  constexpr float kBandEdges[] = {0.0f, 60.0f, 75.0f, 80.0f, 90.0f};
  constexpr int kBands = 4;
  std::vector<float> bands[kBands];
  float perturbation = 0.0f;  // how far the map tilts the layer from the sphere's own normal
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!(raster.at(x, y).a == 1.0f && coverage.at(x, y).r == 1.0f)) continue;
      const glm::vec3 a = glm::vec3(rasterNormal.at(x, y)), b = glm::vec3(referenceNormal.at(x, y));
      ASSERT_GT(glm::length(a), 0.5f);
      ASSERT_GT(glm::length(b), 0.5f);
      const float angle =
          std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * 180.0f / kPi;
      // The unit sphere's own normal at the pixel centre's ray (a covered pixel's centre may miss
      // the sphere's exact silhouette by a hair: such a pixel counts in the outermost band).
      const Ray ray = camera.primaryRay({x + 0.5f, y + 0.5f}, kSize, kSize);
      const float bq = glm::dot(ray.origin, ray.direction);
      const float disc = bq * bq - (glm::dot(ray.origin, ray.origin) - 1.0f);
      float facing = 90.0f;
      if (disc > 0.0f) {
        const glm::vec3 n = glm::normalize(ray.origin + (-bq - std::sqrt(disc)) * ray.direction);
        facing = std::acos(std::clamp(-glm::dot(n, ray.direction), -1.0f, 1.0f)) * 180.0f / kPi;
        perturbation =
            std::max(perturbation, std::acos(std::clamp(glm::dot(n, glm::normalize(b)), -1.0f, 1.0f)));
      }
      int band = 0;
      while (band + 1 < kBands && facing >= kBandEdges[band + 1]) ++band;
      bands[band].push_back(angle);
    }
  float worst = 0.0f;
  std::size_t pixels = 0;
  std::printf("normal-mapped sphere normal layers (the map tilts normals by up to %.1f degrees):\n",
              perturbation * 180.0f / kPi);
  for (int band = 0; band < kBands; ++band) {
    std::vector<float>& angles = bands[band];
    ASSERT_FALSE(angles.empty()) << "no pixel faces the camera at " << kBandEdges[band] << " degrees or more";
    std::sort(angles.begin(), angles.end());
    double mean = 0.0;
    for (float a : angles) mean += a;
    mean /= static_cast<double>(angles.size());
    std::printf("  facing %2.0f to %2.0f degrees: %5zu pixels, mean %.3f, p99 %.3f, max %.3f degrees\n",
                kBandEdges[band], kBandEdges[band + 1], angles.size(), mean, angles[angles.size() * 99 / 100],
                angles.back());
    worst = std::max(worst, angles.back());
    pixels += angles.size();
  }
  // The whole disk is compared, its limb included: 128 px, the sphere about 100 px across.
  EXPECT_GT(pixels, 7500u);
  EXPECT_GT(bands[kBands - 1].size(), 50u);
  EXPECT_LE(worst, 1.0f);
  // The map is really applied (a sphere without it would agree to 0.5 degrees too).
  EXPECT_GT(perturbation * 180.0f / kPi, 10.0f);
}

// 4. A quad with a masked hole (alpha 0 inside a disk, MASK at 0.5) in front of the camera: both
// programs see the environment through the hole, on the same pixels. The raster's alpha and the
// tracer's --mask are each the pixel's coverage by the quad; they agree to a quarter everywhere
// (edge pixels: 16 fixed samples against 32 jittered ones), and where neither covers any of the
// pixel both hold the environment's radiance (the same lat-long lookup) to 0.5%.
TEST_F(TextureAgreement, MaskedHoleShowsTheEnvironmentOnTheSamePixels) {
  const std::vector<std::uint8_t> holed = pixels(64, [](int x, int y) {
    const float dx = x + 0.5f - 32.0f, dy = y + 0.5f - 32.0f;
    return glm::u8vec4(10, 10, 10, dx * dx + dy * dy < 14.0f * 14.0f ? 0 : 255);
  });
  GltfBuilder builder;
  builder.addQuadNode();
  addTexturedMaterial(builder, test::encodePng(64, 64, holed), "baseColorTexture",
                      {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}},
                      {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}});
  builder.write(dir / "quad.glb", GltfBuilder::Storage::Glb);
  writeEnvironment(dir / "coloured.exr", 128, [](const glm::vec3& d) {
    return glm::vec3(1.0f + 0.5f * d.x, 1.0f + 0.5f * d.y, 1.5f - 0.5f * d.z);
  });
  const fs::path scene = writeScene(dir, dir / "quad.glb", dir / "coloured.exr", {0, 0, 2}, {0, 0, 0}, 45.0f);
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "sh", 96, 96));
  ASSERT_NO_FATAL_FAILURE(
      trace(scene, dir / "reference.exr", 96, 96, 32, "--integrator direct --mask " + q(dir / "mask.exr")));
  const Image raster = readExr(dir / "raster.exr"), reference = readExr(dir / "reference.exr");
  const Image coverage = readExr(dir / "mask.exr");
  int holes = 0, quads = 0;
  float worstCoverage = 0.0f, worstRadiance = 0.0f;
  for (std::size_t i = 0; i < raster.pixelCount(); ++i) {
    const float a = raster.pixels()[i].a, b = coverage.pixels()[i].r;
    worstCoverage = std::max(worstCoverage, std::abs(a - b));
    if (a == 0.0f && b == 0.0f) {
      ++holes;
      const glm::vec3 x = glm::vec3(raster.pixels()[i]), y = glm::vec3(reference.pixels()[i]);
      worstRadiance = std::max(worstRadiance, glm::length(x - y) / glm::length(y));
    }
    if (a == 1.0f && b == 1.0f) ++quads;
  }
  std::printf("masked hole: %d hole pixels, %d quad pixels, largest coverage difference %.3f, largest radiance "
              "difference in the hole %.5f\n",
              holes, quads, worstCoverage, worstRadiance);
  // The disk's radius is 14/64 of the quad's side 2 (0.4375), the frame's half-height 0.83: about
  // 96^2 pi (0.4375 / 1.66)^2 = 2000 pixels.
  EXPECT_GT(holes, 1500);
  EXPECT_GT(quads, 4000);
  EXPECT_LE(worstCoverage, 0.25f);
  EXPECT_LT(worstRadiance, 0.005f);
}

// A head-on quad of addQuadNode (cells 1: corners bottom-left, bottom-right, top-left, top-right;
// triangles (BL, BR, TR) and (BL, TR, TL)) with COLOR_0 `corners` in that order, as normalised
// unsigned bytes (VEC4), on material 0.
void addColouredQuad(GltfBuilder& builder, const std::array<glm::u8vec4, 4>& corners) {
  builder.addQuadNode();
  std::vector<std::uint8_t> bytes;
  for (const glm::u8vec4& c : corners)
    for (int k = 0; k < 4; ++k) bytes.push_back(c[k]);
  json& primitive = builder.document()["meshes"].back()["primitives"][0];
  primitive["attributes"]["COLOR_0"] = builder.addAccessor(bytes.data(), bytes.size(), test::kUnsignedByte, 4, "VEC4", true);
}

// scene.json in `dir`: addColouredQuad with `material` as its one material, under a constant
// environment of radiance 1, seen head-on from (0, 0, 2) (headOnPoint's camera).
fs::path colouredQuadScene(const fs::path& dir, const std::array<glm::u8vec4, 4>& corners, const json& material) {
  GltfBuilder builder;
  addColouredQuad(builder, corners);
  builder.document()["materials"] = {material};
  if (material.contains("extensions")) builder.document()["extensionsUsed"] = {"KHR_materials_specular"};
  builder.write(dir / "quad.glb", GltfBuilder::Storage::Glb);
  writeEnvironment(dir / "constant.exr", 64, [](const glm::vec3&) { return glm::vec3(1.0f); });
  return writeScene(dir, dir / "quad.glb", dir / "constant.exr", {0, 0, 2}, {0, 0, 0}, 45.0f);
}

// The quad's interpolated COLOR_0 at (x, y) in [-1, 1]^2 (barycentric in its triangle).
glm::vec4 quadColour(const std::array<glm::u8vec4, 4>& corners, float x, float y) {
  const auto c = [&](int i) { return glm::vec4(corners[std::size_t(i)]) / 255.0f; };
  const float s = 0.5f * (x + 1.0f), t = 0.5f * (y + 1.0f);
  return s >= t ? c(0) * (1.0f - s) + c(1) * (s - t) + c(3) * t : c(0) * (1.0f - t) + c(3) * s + c(2) * (t - s);
}

// The world point on the z = 0 plane that pixel (px, py) of a w x h frame sees from (0, 0, 2)
// looking at the origin with a 45 degree vertical field of view (writeScene's camera below).
glm::vec2 headOnPoint(int px, int py, int w, int h) {
  const float half = 2.0f * std::tan(0.5f * 45.0f * kPi / 180.0f);
  return {(2.0f * (px + 0.5f) / w - 1.0f) * half * w / h, (1.0f - 2.0f * (py + 0.5f) / h) * half};
}

// 5. Vertex colours (glTF COLOR_0) multiply the base colour in both programs. A Lambert quad
// (no specular lobe) under a constant environment of radiance 1: its radiance is the interpolated
// colour times the base colour factor, exactly, in `sh` (SH9 of a constant map is exact) and in the
// reference (a lone plane: no occluder, no interreflection). Each program against that analytic
// image, pixel by pixel (a pixel's filter averages a linear function to its centre's value).
TEST_F(TextureAgreement, VertexColouredQuadMatchesTheAnalyticColours) {
  const std::array<glm::u8vec4, 4> corners = {glm::u8vec4(255, 0, 0, 255), glm::u8vec4(0, 255, 0, 255),
                                              glm::u8vec4(255, 255, 255, 255), glm::u8vec4(0, 0, 255, 255)};
  const fs::path scene = colouredQuadScene(
      dir, corners,
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.9, 1.0, 1.0}}, {"metallicFactor", 0.0}}},
       {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}});
  const int w = 64, h = 64;
  ASSERT_NO_FATAL_FAILURE(trace(scene, dir / "reference.exr", w, h, 256, "--integrator direct"));
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "sh", w, h));
  // iblkit-info tells the user the colours are there.
  std::string info;
  ASSERT_EQ(test::runCommand(q(test::binDir() / "iblkit-info") + " --json " + q(dir / "quad.glb"), &info), 0) << info;
  EXPECT_EQ(json::parse(info)["vertexColorMeshes"], 1) << info;
  const glm::vec3 factor(0.8f, 0.9f, 1.0f);
  for (const char* name : {"reference.exr", "raster.exr"}) {
    const Image image = readExr(dir / name);
    ASSERT_EQ(image.width(), w);
    float worst = 0.0f;
    int wx = 0, wy = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::vec2 p = headOnPoint(x, y, w, h);
        const glm::vec3 expected = factor * glm::vec3(quadColour(corners, p.x, p.y));
        const float d = glm::length(glm::vec3(image.at(x, y)) - expected);
        if (d > worst) worst = d, wx = x, wy = y;
      }
    std::printf("vertex-coloured quad, %s: largest difference from the analytic colour %.4f (pixel %d, %d)\n", name,
                worst, wx, wy);
    EXPECT_LT(worst, 0.02f) << name;
  }
}

// 6. A vertex colour's alpha is alpha: 1 on the quad's left corners, 0 on its right ones, so
// alpha = 1 - s across it (s = (x + 1) / 2) and a MASK at 0.5 keeps the left half (x < 0) in both
// programs, on the same pixels.
TEST_F(TextureAgreement, VertexAlphaMasksTheSamePixels) {
  const std::array<glm::u8vec4, 4> corners = {glm::u8vec4(40, 40, 40, 255), glm::u8vec4(40, 40, 40, 0),
                                              glm::u8vec4(40, 40, 40, 255), glm::u8vec4(40, 40, 40, 0)};
  const fs::path scene = colouredQuadScene(
      dir, corners, {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.5}});
  const int w = 64, h = 64;  // square: the quad fills the frame
  ASSERT_NO_FATAL_FAILURE(view(scene, dir / "raster.exr", "sh", w, h));
  ASSERT_NO_FATAL_FAILURE(
      trace(scene, dir / "reference.exr", w, h, 16, "--integrator direct --mask " + q(dir / "mask.exr")));
  const Image raster = readExr(dir / "raster.exr"), coverage = readExr(dir / "mask.exr");
  int wrong = 0;
  float worst = 0.0f;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float a = raster.at(x, y).a, b = coverage.at(x, y).r;
      worst = std::max(worst, std::abs(a - b));
      // Away from the edge at x = 0 (the middle two columns): all or nothing, the left half there.
      if (x < w / 2 - 1 || x > w / 2) wrong += (a != (x < w / 2 ? 1.0f : 0.0f)) + (b != (x < w / 2 ? 1.0f : 0.0f));
    }
  std::printf("vertex alpha mask: %d pixels off the expected half, largest coverage difference %.3f\n", wrong, worst);
  EXPECT_EQ(wrong, 0);
  EXPECT_LE(worst, 0.5f);
}

// 7. Measured, not bounded (docs/material-model.md "Raster against reference"): a checker on a
// plane seen at 3 to 22 degrees, raster with anisotropic filtering (16, the default) and without
// (1), at the report's sampling and without --sample-shading, against the reference at its
// footprint rule.
TEST_F(TextureAgreement, GrazingCheckerPlaneMeasured) {
  const std::vector<std::uint8_t> checker = pixels(256, [](int x, int y) {
    return ((x / 32 + y / 32) % 2) ? glm::u8vec4(230, 140, 40, 255) : glm::u8vec4(30, 60, 200, 255);
  });
  GltfBuilder builder;
  builder.addQuadNode(10.0f, 10.0f, 20);  // 20 x 20, the texture repeated 10 times: 2 x 2 checks a unit
  builder.document()["nodes"][0]["rotation"] = {-0.70710678, 0.0, 0.0, 0.70710678};  // facing +y
  addTexturedMaterial(builder, test::encodePng(256, 256, checker), "baseColorTexture",
                      {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}},
                      {{"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}});
  builder.document()["extensionsUsed"] = {"KHR_materials_specular"};
  builder.write(dir / "plane.glb", GltfBuilder::Storage::Glb);
  writeEnvironment(dir / "constant.exr", 64, [](const glm::vec3&) { return glm::vec3(1.0f); });
  const fs::path scene = writeScene(dir, dir / "plane.glb", dir / "constant.exr", {0, 0.4f, 8.0f}, {0, 0, 0}, 40.0f);
  ASSERT_NO_FATAL_FAILURE(trace(scene, dir / "reference.exr", 160, 90, 256, "--integrator direct"));
  for (const std::string& sampling : {kReportEngineSettings, std::string(" --samples 4 --supersample 2")})
    for (const char* anisotropy : {"16", "1"}) {
      const fs::path raster = dir / "raster.exr";
      ASSERT_NO_FATAL_FAILURE(view(scene, raster, "sh", 160, 90, std::string("--anisotropy ") + anisotropy, sampling));
      const Image image = readExr(raster);
      std::vector<std::uint8_t> mask(image.pixelCount());
      for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = image.pixels()[i].a > 0.999f ? 1 : 0;
      const ImageScores scores = score(dir / "reference.exr", raster, mask);
      std::printf("grazing checker plane,%s --anisotropy %s: %zu pixels, mean FLIP %.4f, relMSE %.3g\n",
                  sampling.c_str(), anisotropy, scores.scoredPixels, scores.meanFlip, scores.relMse);
      EXPECT_GT(scores.scoredPixels, 3000u);
    }
}

}  // namespace
}  // namespace iblkit
