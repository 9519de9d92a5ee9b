// End-to-end: the iblkit-info program on the whole broken-file corpus (tests/data/bad) and on
// every fetched asset. Each broken file must give exactly one error line on stderr that names the
// file (after any warnings about what was repaired on the way), and a non-zero exit status; files
// the loaders repair (NaN pixels) give a warning and exit 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"
#include "support/usage_error_check.h"

namespace iblkit {
namespace {

std::string info(const std::string& arguments, int* status) {
  std::string output;
  *status = test::runCommand((test::binDir() / "iblkit-info").string() + " " + arguments, &output);
  return output;
}

std::string quoted(const std::filesystem::path& p) {
  std::string text = "'";
  text += p.string();
  text += "'";
  return text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) out.push_back(line);
  return out;
}

// Files whose defects the loaders repair with a warning instead of refusing them.
const std::set<std::string> kRepaired = {"nan_pixels.exr"};

TEST(IblkitInfo, EveryBrokenFileGetsOneLineNamingItAndAFailingExit) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::dataDir() / "bad")) {
    const std::filesystem::path file = entry.path();
    const std::string name = file.filename().string();
    if (file.extension() == ".py" || kRepaired.count(name)) continue;
    int status = 0;
    // stdout is discarded: the one line must be the error on stderr.
    const std::string output = info(quoted(file) + " >/dev/null", &status);
    EXPECT_EQ(status, 1) << name << ": " << output;
    const std::vector<std::string> printed = lines(output);
    ASSERT_FALSE(printed.empty()) << name;
    EXPECT_EQ(printed.back().rfind("iblkit-info: " + file.string() + ": ", 0), 0u) << name << ": " << output;
    for (std::size_t i = 0; i + 1 < printed.size(); ++i)
      EXPECT_EQ(printed[i].rfind(file.string() + ": warning: ", 0), 0u) << name << ": " << output;
    ++checked;
  }
  EXPECT_GE(checked, 19);
}

TEST(IblkitInfo, RepairedPixelsWarnAndSucceed) {
  const std::filesystem::path file = test::dataDir() / "bad" / "nan_pixels.exr";
  int status = 0;
  const std::string output = info(quoted(file) + " >/dev/null", &status);
  EXPECT_EQ(status, 0);
  EXPECT_EQ(output, file.string() + ": warning: 3 NaN, 1 Inf and 2 negative pixel values set to 0\n");
}

TEST(IblkitInfo, GoodFilesStillPrintWhenABadOneFails) {
  const std::filesystem::path good = test::dataDir() / "bad" / "nan_pixels.exr";
  const std::filesystem::path bad = test::dataDir() / "bad" / "garbage.exr";
  int status = 0;
  const std::string output = info("--json " + quoted(bad) + " " + quoted(good) + " 2>/dev/null", &status);
  EXPECT_EQ(status, 1);
  const nlohmann::json d = nlohmann::json::parse(output);
  EXPECT_EQ(d["file"], good.string());
  EXPECT_EQ(d["kind"], "image");
}

// Each texture: the slots and materials using it, size, format, channels, colour space, sampler
// and where its image came from (the glb's buffer, a data: URI, a file).
TEST(IblkitInfo, ListsEachTexture) {
  const std::filesystem::path dir = test::scratchDir();
  test::GltfBuilder builder;
  const std::vector<glm::vec3> triangle = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  const std::vector<glm::vec2> uvs = {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)};
  const int positions = builder.addFloats(triangle), texcoords = builder.addFloats(uvs);
  for (int material = 0; material < 2; ++material)
    builder.addPrimitiveNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", texcoords}}}, {"material", material}});
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/png");
  test::writeFileBytes(dir / "normal.webp", test::encodeWebp(2, 2, test::quadPixels()));
  builder.document()["images"].push_back({{"uri", "normal.webp"}, {"name", "normal"}});
  builder.document()["images"].push_back(
      {{"uri", "data:image/jpeg;base64," + test::base64(test::encodeJpeg(4, 2, std::vector<std::uint8_t>(32, 90)))}});
  builder.document()["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9984}}};
  builder.document()["textures"] = {{{"source", 0}, {"name", "albedo"}},
                                    {{"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}, {"sampler", 0}},
                                    {{"source", 2}}};
  builder.document()["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
       {"emissiveTexture", {{"index", 0}}},
       {"normalTexture", {{"index", 1}}}},
      {{"occlusionTexture", {{"index", 1}}},
       {"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 2}}}, {"baseColorTexture", {{"index", 2}}}}}}};
  const std::filesystem::path glb = dir / "textured.glb";
  builder.write(glb, test::GltfBuilder::Storage::Glb);

  int status = 0;
  const nlohmann::json d = nlohmann::json::parse(info("--json " + quoted(glb) + " 2>/dev/null", &status));
  EXPECT_EQ(status, 0);
  ASSERT_EQ(d["textures"].size(), 3u);
  EXPECT_EQ(d["images"], 3);
  const nlohmann::json& albedo = d["textures"][0];
  EXPECT_EQ(albedo["name"], "albedo");
  EXPECT_EQ(albedo["slots"], nlohmann::json({"baseColorTexture", "emissiveTexture"}));
  EXPECT_EQ(albedo["materials"], nlohmann::json({0}));
  EXPECT_EQ(albedo["colorSpace"], "sRGB");
  EXPECT_EQ(albedo["width"], 2);
  EXPECT_EQ(albedo["mimeType"], "image/png");
  EXPECT_EQ(albedo["channels"], 4);
  EXPECT_EQ(albedo["source"], "bufferView");
  EXPECT_EQ(albedo["wrapS"], "REPEAT");
  EXPECT_EQ(albedo["minFilter"], "LINEAR_MIPMAP_LINEAR");
  const nlohmann::json& normal = d["textures"][1];
  EXPECT_EQ(normal["slots"], nlohmann::json({"normalTexture", "occlusionTexture"}));
  EXPECT_EQ(normal["materials"], nlohmann::json({0, 1}));
  EXPECT_EQ(normal["colorSpace"], "linear");
  EXPECT_EQ(normal["mimeType"], "image/webp");
  EXPECT_EQ(normal["source"], "file");
  EXPECT_EQ(normal["sourceFile"], (dir / "normal.webp").string());
  EXPECT_EQ(normal["wrapS"], "CLAMP_TO_EDGE");
  EXPECT_EQ(normal["wrapT"], "MIRRORED_REPEAT");
  EXPECT_EQ(normal["magFilter"], "NEAREST");
  EXPECT_EQ(normal["minFilter"], "NEAREST_MIPMAP_NEAREST");
  const nlohmann::json& jpeg = d["textures"][2];
  EXPECT_EQ(jpeg["colorSpace"], "sRGB+linear");  // base colour and metallic-roughness
  EXPECT_EQ(jpeg["mimeType"], "image/jpeg");
  EXPECT_EQ(jpeg["channels"], 3);
  EXPECT_EQ(jpeg["width"], 4);
  EXPECT_EQ(jpeg["height"], 2);
  EXPECT_EQ(jpeg["source"], "dataUri");

  const std::vector<std::string> text = lines(info(quoted(glb) + " 2>/dev/null", &status));
  EXPECT_EQ(status, 0);
  EXPECT_NE(std::find(text.begin(), text.end(),
                      "  texture 1: normalTexture, occlusionTexture (material 0, 1), 2x2 image/webp 4 channel(s), "
                      "linear, wrap CLAMP_TO_EDGE/MIRRORED_REPEAT, filter NEAREST/NEAREST_MIPMAP_NEAREST, " +
                          (dir / "normal.webp").string()),
            text.end());
  EXPECT_NE(std::find(text.begin(), text.end(),
                      "  texture 0 'albedo': baseColorTexture, emissiveTexture (material 0), 2x2 image/png 4 channel(s), "
                      "sRGB, wrap REPEAT/REPEAT, filter LINEAR/LINEAR_MIPMAP_LINEAR, embedded (buffer view)"),
            text.end());
}

TEST(IblkitInfo, AllEighteenEnvironmentMapsAndBothModelsLoad) {
  const std::filesystem::path assets = test::assetsDir();
  if (!std::filesystem::exists(assets / "hdri")) GTEST_SKIP() << "assets not fetched";
  int maps = 0;
  for (const auto& entry : std::filesystem::directory_iterator(assets / "hdri")) {
    int status = 0;
    const nlohmann::json d =
        nlohmann::json::parse(info("--json " + quoted(entry.path()) + " 2>/dev/null", &status));
    EXPECT_EQ(status, 0);
    EXPECT_EQ(d["width"], 512);
    EXPECT_EQ(d["height"], 256);
    EXPECT_GT(d["maxLuminance"].get<float>(), 1.0f) << entry.path();
    EXPECT_GT(d["meanLuminance"].get<float>(), 0.0f) << entry.path();
    ++maps;
  }
  EXPECT_EQ(maps, 18);
  for (const auto& [model, vertices] : {std::pair{"bunny.glb", 2826}, std::pair{"suzi.glb", 7503}}) {
    int status = 0;
    const nlohmann::json d =
        nlohmann::json::parse(info("--json " + quoted(assets / "models" / model), &status));
    EXPECT_EQ(status, 0);
    EXPECT_EQ(d["vertices"], vertices);
  }
}

TEST(IblkitInfo, BundledScenesLoad) {
  const std::filesystem::path scenes = test::assetsDir() / "scenes";
  if (!std::filesystem::exists(test::assetsDir() / "models")) GTEST_SKIP() << "assets not fetched";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    int status = 0;
    const std::string output = info("--json " + quoted(entry.path()) + " 2>/dev/null", &status);
    ASSERT_EQ(status, 0) << entry.path() << ": " << output;
    const nlohmann::json d = nlohmann::json::parse(output);
    // The lone spheres stand in the sky; the bunny, suzi and pmndrs.glb stand on a ground plane.
    const bool lone = entry.path().stem().string().ends_with("_sphere");
    EXPECT_EQ(d["groundMeshes"], lone ? 0 : 1) << entry.path();
    EXPECT_TRUE(std::filesystem::exists(scenes / d["environment"].get<std::string>()) ||
                std::filesystem::exists(d["environment"].get<std::string>()))
        << entry.path();
    // The textured scenes (pmndrs.glb as shipped; tiles adds a normal and an occlusion texture
    // in the scene file) list their textures' slots; the others have none.
    std::vector<std::string> slots;
    for (const nlohmann::json& texture : d.value("textures", nlohmann::json::array()))
      for (const nlohmann::json& slot : texture["slots"]) slots.push_back(slot);
    const std::string stem = entry.path().stem().string();
    if (stem == "pmndrs") {
      EXPECT_EQ(slots, std::vector<std::string>{"baseColorTexture"});
    } else if (stem == "tiles") {
      EXPECT_EQ(slots, (std::vector<std::string>{"baseColorTexture", "normalTexture", "occlusionTexture"}));
    } else {
      EXPECT_TRUE(slots.empty()) << entry.path();
    }
    ++count;
  }
  EXPECT_EQ(count, 7);  // mirror_sphere, diffuse_sphere, bunny, bunny_esplanade, suzi, pmndrs, tiles
}

TEST(IblkitInfo, PngPreviewNeedsOneImage) {
  int status = 0;
  const std::string output = info("--png /tmp/x.png a.exr b.exr", &status);
  EXPECT_EQ(status, 2);
  EXPECT_EQ(output, "iblkit-info: --png: needs exactly one image file\n");
}

// A bake folder (bake.json and env/lights.json written by hand): its inputs and its lights, the
// suns' share of the energy from the median-cut regions, which tile the map.
TEST(IblkitInfo, ListsTheLightsOfABakeFolder) {
  const std::filesystem::path bake = test::scratchDir() / "bake";
  std::filesystem::create_directories(bake / "env");
  std::ofstream(bake / "bake.json") << R"({"version": "iblkit-bake 1", "inputs": {"scene": "/s/scene.json",
    "environment": "/s/sky.exr"}, "parameters": {"environment_rotation_degrees": 0, "environment_intensity": 1}})";
  const std::string sh9 = R"("sh9": [[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0],[0,0,0]])";
  std::ofstream(bake / "env" / "lights.json")
      << R"({"kind": "iblkit environment lights", "sunThreshold": 20, "medianCutLevels": 1,
    "suns": [{"direction": [0, 1, 0], "irradiance": [3, 3, 3], "radiance": [6000, 6000, 6000],
      "solidAngle": 0.0005, "angularRadius": 0.0126, "texels": [10, 0, 30, 2], )"
      << sh9 << R"(}],
    "medianCut": [{"direction": [0, 0.8, 0.6], "irradiance": [3.5, 3.5, 3.5], "radiance": [0.6, 0.6, 0.6],
      "solidAngle": 6.2832, "angularRadius": 1.5708, "texels": [0, 0, 64, 16], )"
                  << sh9 << R"(}, {"direction": [0, -1, 0], "irradiance": [0.5, 0.5, 0.5],
      "radiance": [0.08, 0.08, 0.08], "solidAngle": 6.2832, "angularRadius": 1.5708, "texels": [0, 16, 64, 32], )"
                  << sh9 << "}]}";
  int status = 0;
  const std::string text = info(quoted(bake), &status);
  EXPECT_EQ(status, 0) << text;
  const std::vector<std::string> printed = lines(text);
  ASSERT_EQ(printed.size(), 7u) << text;
  EXPECT_EQ(printed[1], "  bake of /s/scene.json under /s/sky.exr");
  EXPECT_EQ(printed[2], "  sun threshold 20: 1 sun(s)");
  EXPECT_EQ(printed[3],
            "    sun 0: direction (0, 1, 0), angular radius 0.722 degrees, irradiance (3, 3, 3), 75% of the energy");
  EXPECT_EQ(printed[4], "  median cut, 1 level(s): 2 light(s)");
  const nlohmann::json d = nlohmann::json::parse(info("--json " + quoted(bake), &status));
  EXPECT_EQ(d["kind"], "bake");
  EXPECT_EQ(d["lights"]["suns"].size(), 1u);
  EXPECT_NEAR(d["lights"]["medianCut"][1]["energyFraction"].get<double>(), 0.125, 1e-6);
  // A folder that is no bake, and a bad lights file: one line naming the file.
  const std::string none = info(quoted(bake / "env"), &status);
  EXPECT_EQ(status, 1);
  EXPECT_EQ(none, "iblkit-info: " + (bake / "env" / "bake.json").string() + ": missing (incomplete bake folder?)\n");
  std::ofstream(bake / "env" / "lights.json") << R"({"kind": "iblkit environment lights"})";
  EXPECT_EQ(info(quoted(bake), &status),
            "iblkit-info: " + (bake / "env" / "lights.json").string() + ": lights: missing \"sunThreshold\"\n");
  EXPECT_EQ(status, 1);
}

// Every program's command-line errors: one line naming the program, status 2 (cli/program.h).
TEST(IblkitInfo, ABadOptionIsOneLineAndStatusTwo) {
  test::expectUsageError((test::binDir() / "iblkit-info").string() + " --json",
                         "iblkit-info: files is required");
}

TEST(IblkitInfo, HelpExitsZero) {
  int status = 0;
  const std::string output = info("--help", &status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(output.find("Usage: iblkit-info"), std::string::npos) << output;
  EXPECT_NE(output.find("Exit status: 0 success, 1 failure at run time"), std::string::npos) << output;
}

}  // namespace
}  // namespace iblkit
