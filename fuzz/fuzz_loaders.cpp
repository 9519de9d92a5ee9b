#include "fuzz/fuzz_loaders.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "bakefile/bake_record.h"
#include "bakefile/environment_lights_json.h"
#include "bakefile/sh9_json.h"
#include "core/error.h"
#include "core/gltf_load.h"
#include "core/image_io.h"
#include "core/input_file.h"
#include "core/scene_file.h"
#include "core/texture_image.h"
#include "reference/pass_sum.h"

namespace iblkit::fuzz {
namespace {

namespace fs = std::filesystem;

void ignoreWarning(const std::string&) {}

// What a fuzzed scene may name beside itself (the seeds do): a one-triangle glTF and a 2x1 .hdr.
constexpr std::string_view kSceneModel =
    R"({"asset":{"version":"2.0"},"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
    R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
    R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":)"
    R"("data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
// A 1 x 1 RGB PNG, albedo.png, for a scene's texture overrides to name.
constexpr char kSceneTextureBytes[] =
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00\x00\x01"
    "\x08\x02\x00\x00\x00\x90\x77\x53\xde\x00\x00\x00\x0c\x49\x44\x41\x54\x78\x9c\x63\x38\x91\x62\x04\x00"
    "\x03\x56\x01\x5f\xe8\x17\x84\x52\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82";
constexpr std::string_view kSceneTexture(kSceneTextureBytes, sizeof(kSceneTextureBytes) - 1);
constexpr std::string_view kSceneEnvironment = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n\x80\x80\x80\x81\x80\x80\x80\x81";

void writeFile(const fs::path& file, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out) std::abort();  // the scratch folder itself failed: not the loader's finding
}

// This process's scratch folder: created on first use, removed when the process exits normally.
// Allocated once and never freed, so the exit handler cannot outlive it.
const fs::path& scratchFolder() {
  static const fs::path* const folder = [] {
    auto* path = new fs::path(fs::temp_directory_path() / ("iblkit-fuzz-" + std::to_string(::getpid())));
    fs::remove_all(*path);
    fs::create_directories(*path);
    writeFile(*path / "model.gltf", kSceneModel);
    writeFile(*path / "env.hdr", kSceneEnvironment);
    writeFile(*path / "albedo.png", kSceneTexture);
    setWarningSink(&ignoreWarning);
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(*folder, ignored);
    });
    return path;
  }();
  return *folder;
}

std::string fileName(Loader loader, std::span<const std::uint8_t> bytes) {
  switch (loader) {
    case Loader::Exr: return "input.exr";
    case Loader::Hdr: return "input.hdr";
    case Loader::Png: return "input.png";
    case Loader::Gltf:
      return bytes.size() >= 4 && std::string_view(reinterpret_cast<const char*>(bytes.data()), 4) == "glTF"
                 ? "input.glb"
                 : "input.gltf";
    case Loader::Scene: return "scene.json";
    case Loader::BakeRecord: return "bake.json";
    case Loader::Sh9: return "sh9.json";
    case Loader::Texture: return "texture.img";
    case Loader::Lights: return "lights.json";
    case Loader::PassSum: return "pass.sum";
  }
  std::abort();
}

void load(Loader loader, const fs::path& file) {
  switch (loader) {
    case Loader::Exr: {
      ExrInfo info;
      readExrLevels(file, &info);
      readExr(file, nullptr, 0, PixelRepair::Keep);
      return;
    }
    case Loader::Hdr: readRadianceHdr(file); return;
    case Loader::Png: readPng(file); return;
    case Loader::Gltf: loadGltf(file); return;
    case Loader::Scene: loadSceneFile(file); return;
    case Loader::BakeRecord: readBakeRecord(file); return;
    case Loader::Sh9: {
      float windowCutoff = 0.0f;
      readSh9Json(file, &windowCutoff);
      return;
    }
    case Loader::Texture: {
      const std::vector<char> bytes = readInputFile(file, kMaxBinaryInputBytes);
      TextureImage image;
      decodeTextureImage(image, std::vector<std::uint8_t>(bytes.begin(), bytes.end()), file, "image");
      return;
    }
    case Loader::Lights: readEnvironmentLightsJson(file); return;
    case Loader::PassSum: readPassSum(file); return;
  }
}

bool strict() {
  static const bool on = [] {
    const char* value = std::getenv("IBLKIT_FUZZ_STRICT");
    return value && std::string(value) == "1";
  }();
  return on;
}

[[noreturn]] void strictFailure(const std::string& what) {
  std::fprintf(stderr, "IBLKIT_FUZZ_STRICT: %s\n", what.c_str());
  std::abort();
}

}  // namespace

bool runLoader(Loader loader, std::span<const std::uint8_t> bytes, std::string* refusal) {
  const fs::path file = scratchFolder() / fileName(loader, bytes);
  writeFile(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  try {
    load(loader, file);
    return true;
  } catch (const Error& e) {
    if (refusal) *refusal = e.what();
    if (strict()) {
      const std::string message = e.what();
      if (message.find_first_of("\n\r") != std::string::npos) strictFailure("message of several lines: " + message);
      if (message.find(file.string()) == std::string::npos) strictFailure("message names no input: " + message);
    }
    return false;
  } catch (const std::exception& e) {
    if (refusal) *refusal = e.what();
    if (strict()) strictFailure(std::string("not an iblkit::Error: ") + e.what());
    return false;
  }
}

}  // namespace iblkit::fuzz
