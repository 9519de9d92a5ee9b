// End-to-end: the bad inputs of the outside fuzz campaign (issue 13), each generated here, given to
// the real programs. Each must fail with exactly one line on stderr that names the input at fault
// (the file, and the key or node where there is one) and the exit status of README.md: no crash,
// no hang, no message from deep inside a library.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/image_io.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

struct Result {
  int status = 0;
  std::vector<std::string> lines;  // stderr, stdout discarded
  std::string text;
};

// Runs `program` with `arguments` under a 60 s timeout (a hang fails rather than blocks).
Result run(const std::string& program, const std::string& arguments) {
  Result result;
  const std::string command =
      "timeout 60 " + test::shellQuoted(test::binDir() / program) + " " + arguments + " 2>&1 >/dev/null";
  result.status = test::runCommand(command, &result.text);
  std::istringstream stream(result.text);
  for (std::string line; std::getline(stream, line);)
    if (line.find(": warning: ") == std::string::npos) result.lines.push_back(line);
  return result;
}

// One error line, "PROGRAM: " then `expected` somewhere in it, no control characters, `status`.
void expectOneLine(const Result& result, const std::string& program, int status, const std::string& expected) {
  EXPECT_EQ(result.status, status) << result.text;
  ASSERT_EQ(result.lines.size(), 1u) << result.text;
  const std::string& line = result.lines[0];
  EXPECT_EQ(line.rfind(program + ": ", 0), 0u) << line;
  EXPECT_NE(line.find(expected), std::string::npos) << "expected '" << expected << "' in: " << line;
  for (const char c : line) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20) << "control character in: " << line;
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

std::string q(const fs::path& path) { return test::shellQuoted(path); }

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratchDir();
    writeExr(dir_ / "map.exr", Image(16, 8, glm::vec4(1.0f)));
  }

  // A scene of one sphere lit by map.exr, `models` and `environment` replaced when given.
  fs::path scene(const std::string& name, const std::string& extra, const std::string& models = {},
                 const std::string& environment = {}) {
    const fs::path file = dir_ / name;
    writeText(file, "{\"models\": " + (models.empty() ? std::string("[{\"shape\": \"sphere\"}]") : models) +
                        ", \"environment\": " +
                        (environment.empty() ? std::string("{\"file\": \"map.exr\"}") : environment) +
                        ", \"width\": 8, \"height\": 8" + extra + "}");
    return file;
  }

  Result trace(const fs::path& sceneFile, const std::string& more = {}) {
    return run("iblkit-trace", q(sceneFile) + " -o " + q(dir_ / "out.exr") + " --spp 1 " + more);
  }
  Result bake(const fs::path& sceneFile, const std::string& more = {}) {
    return run("iblkit-bake", q(sceneFile) + " -o " + q(dir_ / "baked") + " --ao-rays 4 --specular-samples 4 " + more);
  }

  fs::path dir_;
};

// A JSON value nested `depth` arrays deep.
std::string deepArray(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

std::string glbAround(std::string json) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string glb = "glTF";
  const auto u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(std::uint32_t(20 + json.size()));
  u32(std::uint32_t(json.size()));
  u32(0x4E4F534Au);
  return glb + json;
}

// Crash 1: tinygltf turns extras into Values recursively; 100,000 levels overflowed the stack.
TEST_F(BadInput, DeeplyNestedGlbIsRefused) {
  const fs::path glb = dir_ / "deep.glb";
  writeText(glb, glbAround("{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + deepArray(100000) + "}"));
  expectOneLine(run("iblkit-info", q(glb)), "iblkit-info", 1, glb.string() + ": JSON nests");
  expectOneLine(trace(glb), "iblkit-trace", 1, glb.string() + ": JSON nests");
  const fs::path gltf = dir_ / "deep.gltf";
  writeText(gltf, "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + deepArray(100000) + "}");
  expectOneLine(run("iblkit-info", q(gltf)), "iblkit-info", 1, gltf.string() + ": JSON nests");
  const fs::path json = scene("deep.json", ", \"camera\": " + deepArray(100000));
  expectOneLine(trace(json), "iblkit-trace", 1, json.string() + ": JSON nests");
}

// Crash 2: Embree asserted (ray.valid()) on a ground 1e30 wide or high.
TEST_F(BadInput, HugeGroundIsRefusedNamingTheKey) {
  const fs::path size = scene("size.json", ", \"ground\": {\"size\": 1e30}");
  expectOneLine(bake(size), "iblkit-bake", 1, size.string() + ": ground.size");
  const fs::path height = scene("height.json", ", \"ground\": {\"height\": 1e30}");
  expectOneLine(bake(height), "iblkit-bake", 1, height.string() + ": ground.height");
  expectOneLine(trace(height), "iblkit-trace", 1, height.string() + ": ground.height");
}

// Crash 3: TBB crashed on an arena of 70,000 threads.
TEST_F(BadInput, ThreadCountIsCapped) {
  const fs::path file = scene("scene.json", "");
  expectOneLine(trace(file, "--threads 70000"), "iblkit-trace", 2, "--threads");
  expectOneLine(bake(file, "--threads 70000"), "iblkit-bake", 2, "--threads");
}

// A single-part, uncompressed scanline OpenEXR with one FLOAT channel R, `width` x 1 pixels, whose
// one chunk holds `storedPixels` pixels, followed by `padding` bytes that belong to no chunk.
void writeShortChunkExr(const fs::path& file, int width, int storedPixels, std::size_t padding = 0) {
  std::string exr("\x76\x2f\x31\x01", 4);
  const auto i32 = [&](std::int32_t v) { exr.append(reinterpret_cast<const char*>(&v), 4); };
  const auto f32 = [&](float v) { exr.append(reinterpret_cast<const char*>(&v), 4); };
  const auto attribute = [&](const char* name, const char* type, std::int32_t size) {
    exr.append(name, std::strlen(name) + 1);
    exr.append(type, std::strlen(type) + 1);
    i32(size);
  };
  i32(2);
  attribute("channels", "chlist", 18 + 1);
  exr.append("R\0", 2);
  i32(2);  // FLOAT
  exr.append("\0\0\0\0", 4);
  i32(1);
  i32(1);
  exr.push_back('\0');
  attribute("compression", "compression", 1);
  exr.push_back('\0');
  for (const char* window : {"dataWindow", "displayWindow"}) {
    attribute(window, "box2i", 16);
    i32(0), i32(0), i32(width - 1), i32(0);
  }
  attribute("lineOrder", "lineOrder", 1);
  exr.push_back('\0');
  attribute("pixelAspectRatio", "float", 4);
  f32(1.0f);
  attribute("screenWindowCenter", "v2f", 8);
  f32(0.0f), f32(0.0f);
  attribute("screenWindowWidth", "float", 4);
  f32(1.0f);
  exr.push_back('\0');
  const std::uint64_t chunk = exr.size() + 8;
  exr.append(reinterpret_cast<const char*>(&chunk), 8);
  i32(0);
  i32(4 * storedPixels);
  for (int i = 0; i < storedPixels; ++i) f32(0.5f);
  exr.append(padding, '\0');
  writeText(file, exr);
}

// Crash 5: OpenEXR copied a 1-pixel chunk into a 20,001-pixel line (at 1,001 it read garbage).
TEST_F(BadInput, ExrChunkShorterThanItsLinesIsRefused) {
  for (const int width : {1001, 20001}) {
    const fs::path file = dir_ / ("wide" + std::to_string(width) + ".exr");
    writeShortChunkExr(file, width, 1);
    // The file is too small for its data window: refused before OpenEXR allocates anything.
    expectOneLine(run("iblkit-info", q(file)), "iblkit-info", 1,
                  file.string() + ": data window of " + std::to_string(width) + " x 1 pixels holds more data");
    // Padded to the size the window needs, the one chunk is still short: refused by the chunk check.
    const fs::path padded = dir_ / ("padded" + std::to_string(width) + ".exr");
    writeShortChunkExr(padded, width, 1, 4 * static_cast<std::size_t>(width));
    expectOneLine(run("iblkit-info", q(padded)), "iblkit-info", 1,
                  padded.string() + ": scanline chunk at y 0 holds 4 bytes");
  }
  const fs::path whole = dir_ / "whole.exr";  // the same layout, complete, reads
  writeShortChunkExr(whole, 8, 8);
  EXPECT_EQ(run("iblkit-info", q(whole)).status, 0);
}

// Hangs: /dev/zero grew memory without end; a FIFO blocked the open.
TEST_F(BadInput, SpecialFilesAreRefusedWithoutReading) {
  const fs::path zero = scene("zero.json", "", "[{\"file\": \"/dev/zero\"}]");
  expectOneLine(trace(zero), "iblkit-trace", 1, "/dev/zero: not a regular file");
  const fs::path fifo = dir_ / "fifo.glb";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path viaFifo = scene("fifo.json", "", "[{\"file\": \"fifo.glb\"}]");
  expectOneLine(trace(viaFifo), "iblkit-trace", 1, "fifo.glb: not a regular file (a FIFO)");
  expectOneLine(run("iblkit-info", q(fifo)), "iblkit-info", 1, fifo.string() + ": not a regular file (a FIFO)");
  ASSERT_EQ(::mkfifo((dir_ / "pipe.json").c_str(), 0600), 0);
  expectOneLine(trace(dir_ / "pipe.json"), "iblkit-trace", 1, "pipe.json: not a regular file (a FIFO)");
  // A map given on the command line: the bake's map reader says what the file is, not that it is missing.
  const fs::path fifoMap = dir_ / "fifo.exr";
  ASSERT_EQ(::mkfifo(fifoMap.c_str(), 0600), 0);
  expectOneLine(bake(scene("plain.json", ""), "--env " + q(fifoMap)), "iblkit-bake", 1,
                fifoMap.string() + ": not a regular file (a FIFO)");
}

// "prefilterSpecular: 1 levels ..." named no file.
TEST_F(BadInput, MapTooSmallToBakeIsNamed) {
  writeExr(dir_ / "tiny.exr", Image(2, 1, glm::vec4(1.0f)));
  const fs::path file = scene("tiny.json", "", {}, "{\"file\": \"tiny.exr\"}");
  expectOneLine(bake(file), "iblkit-bake", 1, "tiny.exr: lat-long map is 2x1");
}

// "EnvironmentMap: rotation must be finite", "PiecewiseConstant2D: value ... is inf".
TEST_F(BadInput, EnvironmentRotationAndIntensityNameTheSceneKey) {
  const fs::path rotation = scene("rotation.json", "", {}, "{\"file\": \"map.exr\", \"rotation\": 1e300}");
  expectOneLine(trace(rotation), "iblkit-trace", 1, rotation.string() + ": environment.rotation");
  const fs::path intensity = scene("intensity.json", "", {}, "{\"file\": \"map.exr\", \"intensity\": 1e38}");
  expectOneLine(trace(intensity), "iblkit-trace", 1, intensity.string() + ": environment.intensity");
  expectOneLine(bake(intensity), "iblkit-bake", 1, intensity.string() + ": environment.intensity");
  expectOneLine(trace(scene("plain.json", ""), "--env-intensity 1e38"), "iblkit-trace", 2, "--env-intensity");
}

// "ray scene mesh 0: vertex 0 has a non-finite position" (1e200), NaN at write time (1e25).
TEST_F(BadInput, ModelScaleOverflowNamesTheSceneKeyAndModel) {
  for (const char* scale : {"1e200", "1e25"}) {
    const fs::path file = scene(std::string("scale") + scale + ".json", "",
                                std::string("[{\"shape\": \"sphere\", \"scale\": ") + scale + "}]");
    expectOneLine(trace(file), "iblkit-trace", 1, file.string() + ": models[0]: translation, rotation and scale");
    expectOneLine(bake(file), "iblkit-bake", 1, file.string() + ": models[0]: translation, rotation and scale");
  }
}

// "[json.exception.out_of_range.406] number overflow parsing '1e999'" named no file.
TEST_F(BadInput, NumberOverflowInSceneNamesTheScene) {
  const fs::path file = scene("overflow.json", ", \"ground\": {\"size\": 1e999}");
  expectOneLine(trace(file), "iblkit-trace", 1, file.string() + ": invalid JSON");
}

// A Radiance file whose pixels are 255 x 2^119: NaN was caught only when writing the output.
TEST_F(BadInput, HdrExponent255NamesTheMap) {
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
  hdr += std::string(4 * 8, '\xff');
  writeText(dir_ / "bright.hdr", hdr);
  const fs::path file = scene("bright.json", "", {}, "{\"file\": \"bright.hdr\"}");
  expectOneLine(trace(file), "iblkit-trace", 1, "bright.hdr: lat-long map has 8 pixels");
}

// The resolution line was echoed raw, carriage return and all.
TEST_F(BadInput, HdrResolutionLineIsQuotedPrintable) {
  const fs::path file = dir_ / "cr.hdr";
  writeText(file, std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2\r +X 4\x1b[2J\n") + std::string(32, '\x80'));
  expectOneLine(run("iblkit-info", q(file)), "iblkit-info", 1, file.string() + ": bad resolution string \"-Y 2? +X 4?[2J\"");
}

// --exposure nan and --exposure-range nan nan were accepted; --phong 1e30 gave NaN pixels.
TEST_F(BadInput, NonFiniteOptionsAreUsageErrors) {
  const fs::path file = scene("scene.json", "");
  expectOneLine(trace(file, "--exposure nan"), "iblkit-trace", 2, "--exposure: must be a finite number, not 'nan'");
  expectOneLine(trace(file, "--env-rotation inf"), "iblkit-trace", 2, "--env-rotation");
  expectOneLine(trace(file, "--phong 1e30"), "iblkit-trace", 2, "--phong");
  expectOneLine(run("iblkit-score", q(dir_ / "map.exr") + " " + q(dir_ / "map.exr") + " --exposure-range nan nan"),
                "iblkit-score", 2, "--exposure-range: must be a finite number, not 'nan'");
}

// Issue 14's bad textures: each is one line naming the glTF file, the texture and the image, for
// iblkit-info and for iblkit-trace (a .glb / .gltf traced directly, and inside a .json scene).
class BadTexture : public BadInput {
 protected:
  // A textured triangle (baseColorTexture = texture 0 = image 0) written as `name`, the document
  // edited by `edit` first.
  fs::path model(const std::string& name, const std::function<void(test::GltfBuilder&)>& edit) {
    test::GltfBuilder builder;
    const std::vector<glm::vec3> triangle = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    const std::vector<glm::vec2> uvs = {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)};
    builder.addPrimitiveNode(
        {{"attributes", {{"POSITION", builder.addFloats(triangle)}, {"TEXCOORD_0", builder.addFloats(uvs)}}},
         {"material", 0}});
    builder.document()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    builder.document()["textures"] = {{{"source", 0}}};
    edit(builder);
    const fs::path file = dir_ / name;
    builder.write(file, name.ends_with(".glb") ? test::GltfBuilder::Storage::Glb : test::GltfBuilder::Storage::BinFile);
    return file;
  }

  // The glTF file through iblkit-info, iblkit-trace, and iblkit-trace of a scene naming it.
  void expectEverywhere(const fs::path& file, const std::string& expected) {
    const std::string message = file.string() + ": " + expected;
    expectOneLine(run("iblkit-info", q(file)), "iblkit-info", 1, message);
    expectOneLine(trace(file), "iblkit-trace", 1, message);
    const fs::path json = scene(file.stem().string() + ".json", "", "[{\"file\": \"" + file.filename().string() + "\"}]");
    expectOneLine(trace(json), "iblkit-trace", 1, message);
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
  }
};

TEST_F(BadTexture, MissingImageFile) {
  const fs::path file = model("missing.gltf", [](test::GltfBuilder& b) { b.document()["images"] = {{{"uri", "albedo.png"}}}; });
  expectEverywhere(file, "texture 0 image 0 'albedo.png': " + (dir_ / "albedo.png").string() +
                             ": cannot open: No such file or directory");
}

TEST_F(BadTexture, ImageThatDoesNotDecode) {
  const fs::path file = model("garbage.glb", [](test::GltfBuilder& b) {
    std::vector<std::uint8_t> png = test::encodePng(4, 4, std::vector<std::uint8_t>(64, 77));
    for (std::size_t i = 40; i < png.size() - 12; ++i) png[i] ^= 0x5a;  // the IDAT data scrambled
    b.addImage(png, "image/png");
  });
  expectEverywhere(file, "texture 0 image 0: PNG does not decode (");
  const fs::path webp = model("garbage_webp.glb", [](test::GltfBuilder& b) {
    std::vector<std::uint8_t> bytes = test::encodeWebp(4, 4, std::vector<std::uint8_t>(64, 77));
    bytes.resize(bytes.size() / 2);
    b.addImage(bytes, "image/webp");
  });
  expectEverywhere(webp, "texture 0 image 0: WebP does not decode (");
}

TEST_F(BadTexture, TextureOrImageIndexOutOfRange) {
  const fs::path texture = model("texture_index.gltf", [](test::GltfBuilder& b) {
    b.document()["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 7;
  });
  expectEverywhere(texture, "material 0 baseColorTexture: texture 7 does not exist");
  const fs::path image = model("image_index.gltf", [](test::GltfBuilder& b) { b.document()["textures"][0]["source"] = 3; });
  expectEverywhere(image, "texture 0: image 3 does not exist");
}

TEST_F(BadTexture, UriThatEscapesTheFolder) {
  fs::create_directories(dir_ / "inner");
  test::writeFileBytes(dir_ / "outside.png", test::encodePng(2, 2, test::quadPixels()));
  int files = 0;
  const auto inner = [&](const std::string& uri) {
    return model("inner/escape" + std::to_string(files++) + ".gltf",
                 [&](test::GltfBuilder& b) { b.document()["images"] = {{{"uri", uri}}}; });
  };
  // The file exists; only the rule stops it.
  const fs::path relative = inner("../outside.png");
  const std::string message = relative.string() + ": texture 0 image 0 '../outside.png': uri '../outside.png' points "
                                                  "outside the scene folder";
  expectOneLine(run("iblkit-info", q(relative)), "iblkit-info", 1, message);
  expectOneLine(trace(relative), "iblkit-trace", 1, message);
  const std::string absolute = (dir_ / "outside.png").string();
  const fs::path absoluteFile = inner(absolute);
  expectOneLine(run("iblkit-info", q(absoluteFile)), "iblkit-info", 1,
                absoluteFile.string() + ": texture 0 image 0 '" + absolute + "': uri '" + absolute +
                    "' points outside the scene folder");
}

TEST_F(BadTexture, MimeTypeWeDoNotRead) {
  const std::vector<std::uint8_t> ktx2 = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n', 0, 0, 0, 0};
  const fs::path declared = model("ktx2.glb", [&](test::GltfBuilder& b) { b.addImage(ktx2, "image/ktx2"); });
  expectEverywhere(declared,
                   "texture 0 image 0: mime type image/ktx2 is not supported (image/png, image/jpeg and image/webp are)");
  test::writeFileBytes(dir_ / "albedo.ktx2", ktx2);
  const fs::path basisu = model("basisu.gltf", [&](test::GltfBuilder& b) {
    b.document()["images"] = {{{"uri", "albedo.ktx2"}}};
    b.document()["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};
  });
  expectEverywhere(basisu, "texture 0 has only a KHR_texture_basisu (KTX2) image, which is not supported");
  const fs::path file = model("ktx2_file.gltf", [&](test::GltfBuilder& b) { b.document()["images"] = {{{"uri", "albedo.ktx2"}}}; });
  expectEverywhere(file, "texture 0 image 0 'albedo.ktx2': KTX2 images (KHR_texture_basisu) are not supported");
}

TEST_F(BadTexture, EmptyImage) {
  const fs::path file = model("empty.glb", [](test::GltfBuilder& b) { b.addImage(test::pngHeaderClaiming(0, 0), "image/png"); });
  expectEverywhere(file, "texture 0 image 0: image is 0 x 0 pixels");
}

// The header claims 64k x 64k (16 GiB of RGBA): refused from the header, nothing allocated (the
// programs run under the test's 60 s timeout, and a 16 GiB allocation would fail or swap).
TEST_F(BadTexture, ImageOf64kBy64k) {
  const fs::path png = model("huge.glb", [](test::GltfBuilder& b) { b.addImage(test::pngHeaderClaiming(65536, 65536), "image/png"); });
  expectEverywhere(png, "texture 0 image 0: image is 65536 x 65536 pixels, beyond the limit of 16384 on a side");
  // WebP's VP8X canvas holds up to 2^24 a side; libwebp refuses 2^32 pixels itself, so 60000.
  const fs::path webp = model("huge_webp.glb", [](test::GltfBuilder& b) { b.addImage(test::webpHeaderClaiming(60000, 60000), "image/webp"); });
  expectEverywhere(webp, "texture 0 image 0: image is 60000 x 60000 pixels, beyond the limit of 16384 on a side");
}

// A scene file's texture override: the key and the file.
TEST_F(BadTexture, SceneOverrideWithAMissingNormalMap) {
  const fs::path file =
      scene("override.json", "", "[{\"shape\": \"sphere\", \"material\": {\"normalTexture\": {\"file\": \"n.webp\"}}}]");
  expectOneLine(trace(file), "iblkit-trace", 1,
                file.string() + ": models[0].material.normalTexture 'n.webp': " + (dir_ / "n.webp").string() +
                    ": cannot open: No such file or directory");
}

}  // namespace
}  // namespace iblkit
