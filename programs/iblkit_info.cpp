// iblkit-info FILE...: what iblkit reads from images, environment maps, glTF models, scene files
// and bake folders: size, layout and pixel statistics; meshes, triangles, materials, bounds, camera
// and environment; or a bake's inputs and the dominant lights of its env/lights.json
// (docs/dominant-lights.md). `--json` prints one JSON object per file; `--png OUT` writes a
// tone-mapped preview of one image. A file that cannot be read gets one line on stderr, the other files are still
// described, and the exit status is 1 (cli/program.h).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/environment_lights_json.h"
#include "cli/program.h"
#include "core/cube_map.h"
#include "core/environment_map.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/usage_error.h"

namespace {

using iblkit::Image;
using nlohmann::json;

std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool isImage(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".exr" || ext == ".hdr" || ext == ".pic" || ext == ".png";
}

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

std::string vec3Text(const glm::vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
  return text;
}

const char* layoutName(iblkit::EnvmapLayout layout) {
  switch (layout) {
    case iblkit::EnvmapLayout::LatLong:
      return "latlong";
    case iblkit::EnvmapLayout::Cube:
      return "cube";
    case iblkit::EnvmapLayout::None:
      break;
  }
  return "none";
}

json describeImage(const std::filesystem::path& file, Image* pixels) {
  iblkit::ExrInfo info;
  *pixels = lowerExtension(file) == ".exr" ? iblkit::readExr(file, &info) : iblkit::readImage(file);
  // A file that declares itself an environment map must be one.
  if (info.envmap == iblkit::EnvmapLayout::LatLong) iblkit::EnvironmentMap::fromImage(*pixels, file);
  if (info.envmap == iblkit::EnvmapLayout::Cube) iblkit::cubeFromExrStrip(*pixels, file);
  const Image::Stats s = pixels->stats();
  return {{"file", file.string()},
          {"kind", "image"},
          {"width", pixels->width()},
          {"height", pixels->height()},
          {"envmap", layoutName(info.envmap)},
          {"levels", info.levels},
          {"latLongAspect", pixels->width() == 2 * pixels->height()},
          {"min", vec3Json(s.min)},
          {"max", vec3Json(s.max)},
          {"mean", vec3Json(s.mean)},
          {"maxLuminance", s.maxLuminance},
          {"meanLuminance", s.meanLuminance}};
}

const char* wrapName(iblkit::TextureWrap wrap) {
  switch (wrap) {
    case iblkit::TextureWrap::ClampToEdge:
      return "CLAMP_TO_EDGE";
    case iblkit::TextureWrap::MirroredRepeat:
      return "MIRRORED_REPEAT";
    case iblkit::TextureWrap::Repeat:
      break;
  }
  return "REPEAT";
}

const char* filterName(iblkit::TextureFilter filter) {
  return filter == iblkit::TextureFilter::Nearest ? "NEAREST" : "LINEAR";
}

// The glTF (GL) name of a sampler's minification: NEAREST, LINEAR or <min>_MIPMAP_<mip>.
std::string minFilterName(const iblkit::TextureSampler& sampler) {
  std::string name = filterName(sampler.minFilter);
  if (sampler.mipmaps) name += std::string("_MIPMAP_") + filterName(sampler.mipFilter);
  return name;
}

// Each texture the scene's materials use: the slots reading it (and which materials), the image's
// size, format, channels and where it came from, the colour space the slots read it in (sRGB for
// base colour and emissive, linear for the others; texture.h) and its sampler.
json describeTextures(const iblkit::Scene& scene) {
  struct Use {
    std::vector<std::string> slots;
    std::vector<int> materials;
    bool srgb = false, linear = false;
  };
  std::vector<Use> uses(scene.textures.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const iblkit::Material& material = scene.materials[m];
    const std::pair<const char*, const iblkit::TextureRef*> slots[] = {
        {"baseColorTexture", &material.baseColorTexture},
        {"metallicRoughnessTexture", &material.metallicRoughnessTexture},
        {"normalTexture", &material.normalTexture},
        {"occlusionTexture", &material.occlusionTexture},
        {"emissiveTexture", &material.emissiveTexture}};
    for (const auto& [slot, ref] : slots) {
      if (!ref->present() || ref->texture >= int(uses.size())) continue;
      Use& use = uses[ref->texture];
      if (std::find(use.slots.begin(), use.slots.end(), slot) == use.slots.end()) use.slots.push_back(slot);
      if (use.materials.empty() || use.materials.back() != int(m)) use.materials.push_back(int(m));
      const bool srgb = ref == &material.baseColorTexture || ref == &material.emissiveTexture;
      (srgb ? use.srgb : use.linear) = true;
    }
  }
  json textures = json::array();
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const iblkit::Texture& texture = scene.textures[t];
    const Use& use = uses[t];
    json d = {{"index", t},
              {"name", texture.name},
              {"slots", use.slots},
              {"materials", use.materials},
              {"colorSpace", use.srgb && use.linear ? "sRGB+linear" : use.srgb ? "sRGB" : "linear"},
              {"wrapS", wrapName(texture.sampler.wrapS)},
              {"wrapT", wrapName(texture.sampler.wrapT)},
              {"magFilter", filterName(texture.sampler.magFilter)},
              {"minFilter", minFilterName(texture.sampler)},
              {"image", texture.image}};
    if (texture.image >= 0 && texture.image < int(scene.images.size())) {
      const iblkit::TextureImage& image = scene.images[texture.image];
      d["width"] = image.width;
      d["height"] = image.height;
      d["mimeType"] = image.mimeType;
      d["channels"] = image.channels;
      d["bytes"] = image.encoded.size();
      d["source"] = image.uri.empty() ? "bufferView" : image.uri.rfind("data:", 0) == 0 ? "dataUri" : "file";
      d["sourceFile"] = image.file.string();
    }
    textures.push_back(std::move(d));
  }
  return textures;
}

json describeScene(const std::filesystem::path& file) {
  const iblkit::Scene scene = iblkit::loadScene(file);
  std::size_t vertices = 0, triangles = 0, groundMeshes = 0, colouredMeshes = 0;
  for (const iblkit::Mesh& mesh : scene.meshes) {
    colouredMeshes += mesh.colors.empty() ? 0 : 1;
    vertices += mesh.vertexCount();
    triangles += mesh.triangleCount();
    groundMeshes += mesh.isGround ? 1 : 0;
  }
  json attributes = json::array();
  for (const iblkit::Mesh& mesh : scene.meshes)
    for (const auto& [name, attribute] : mesh.attributes)
      if (std::find(attributes.begin(), attributes.end(), name) == attributes.end())
        attributes.push_back(name);
  return {{"file", file.string()},
          {"kind", "scene"},
          {"meshes", scene.meshes.size()},
          {"groundMeshes", groundMeshes},
          {"vertices", vertices},
          {"triangles", triangles},
          {"materials", scene.materials.size()},
          {"textures", describeTextures(scene)},
          {"images", scene.images.size()},
          {"customAttributes", attributes},
          {"vertexColorMeshes", colouredMeshes},
          {"boundsMin", vec3Json(scene.bounds.min)},
          {"boundsMax", vec3Json(scene.bounds.max)},
          {"camera", scene.camera ? "scene" : "framed"},
          {"environment", scene.environment.file.string()},
          {"environmentRotation", scene.environment.rotationDegrees},
          {"environmentIntensity", scene.environment.intensity},
          {"size", json::array({scene.width, scene.height})}};
}

// One light of env/lights.json; `share` its part of the map's energy (the median-cut regions tile
// the map, so their summed luminance is the whole), or negative when unknown.
json describeLight(const iblkit::EnvironmentLight& light, double share) {
  json d = {{"direction", vec3Json(light.direction)},
            {"angularRadiusDegrees", glm::degrees(light.angularRadius)},
            {"solidAngle", light.solidAngle},
            {"irradiance", vec3Json(light.irradiance)},
            {"radiance", vec3Json(light.radiance)}};
  if (share >= 0.0) d["energyFraction"] = share;
  return d;
}

// A bake folder: what it was baked from and the lights of env/lights.json (null: a bake without).
json describeBake(const std::filesystem::path& folder) {
  const iblkit::BakeInputs inputs = iblkit::readBakeRecord(folder / iblkit::kBakeRecordFile);
  json d = {{"file", folder.string()},
            {"kind", "bake"},
            {"scene", inputs.scene.string()},
            {"environment", inputs.environment.string()},
            {"lights", nullptr}};
  if (!std::filesystem::exists(folder / iblkit::kBakeLightsFile)) return d;
  const iblkit::EnvironmentLights lights = iblkit::readEnvironmentLightsJson(folder / iblkit::kBakeLightsFile);
  double total = 0.0;
  for (const iblkit::EnvironmentLight& light : lights.medianCut) total += iblkit::luminance(light.irradiance);
  const auto list = [&](const std::vector<iblkit::EnvironmentLight>& entries) {
    json out = json::array();
    for (const iblkit::EnvironmentLight& light : entries)
      out.push_back(describeLight(light, total > 0.0 ? iblkit::luminance(light.irradiance) / total : -1.0));
    return out;
  };
  d["lights"] = {{"sunThreshold", lights.sunThreshold},
                 {"suns", list(lights.suns)},
                 {"medianCutLevels", lights.medianCutLevels},
                 {"medianCut", list(lights.medianCut)}};
  return d;
}

void printLights(const json& lights) {
  const auto print = [](const char* name, const json& light, std::size_t index) {
    const auto v = [&](const char* key) {
      return vec3Text(glm::vec3(light[key][0].get<float>(), light[key][1].get<float>(), light[key][2].get<float>()));
    };
    std::printf("    %s %zu: direction %s, angular radius %.3g degrees, irradiance %s", name, index,
                v("direction").c_str(), light["angularRadiusDegrees"].get<float>(), v("irradiance").c_str());
    if (light.contains("energyFraction"))
      std::printf(", %.3g%% of the energy", 100.0 * light["energyFraction"].get<double>());
    std::printf("\n");
  };
  std::printf("  sun threshold %.4g: %zu sun(s)\n", lights["sunThreshold"].get<float>(), lights["suns"].size());
  for (std::size_t i = 0; i < lights["suns"].size(); ++i) print("sun", lights["suns"][i], i);
  std::printf("  median cut, %d level(s): %zu light(s)\n", lights["medianCutLevels"].get<int>(),
              lights["medianCut"].size());
  for (std::size_t i = 0; i < lights["medianCut"].size(); ++i) print("region", lights["medianCut"][i], i);
}

void printText(const json& d) {
  std::printf("%s\n", d["file"].get<std::string>().c_str());
  if (d["kind"] == "image") {
    std::printf("  image %dx%d, envmap %s, %d level(s)%s\n", d["width"].get<int>(), d["height"].get<int>(),
                d["envmap"].get<std::string>().c_str(), d["levels"].get<int>(),
                d["latLongAspect"].get<bool>() ? ", 2:1 (lat-long)" : "");
    const auto v = [&](const char* key) {
      return vec3Text(glm::vec3(d[key][0].get<float>(), d[key][1].get<float>(), d[key][2].get<float>()));
    };
    std::printf("  min %s max %s mean %s\n", v("min").c_str(), v("max").c_str(), v("mean").c_str());
    std::printf("  luminance max %.4g mean %.4g\n", d["maxLuminance"].get<float>(),
                d["meanLuminance"].get<float>());
    return;
  }
  if (d["kind"] == "bake") {
    std::printf("  bake of %s", d["scene"].get<std::string>().c_str());
    if (!d["environment"].get<std::string>().empty())
      std::printf(" under %s", d["environment"].get<std::string>().c_str());
    std::printf("\n");
    if (d["lights"].is_null())
      std::printf("  no lights (no %s)\n", iblkit::kBakeLightsFile);
    else
      printLights(d["lights"]);
    return;
  }
  std::printf("  %zu mesh(es) (%zu ground), %zu vertices, %zu triangles, %zu material(s)\n",
              d["meshes"].get<std::size_t>(), d["groundMeshes"].get<std::size_t>(),
              d["vertices"].get<std::size_t>(), d["triangles"].get<std::size_t>(),
              d["materials"].get<std::size_t>());
  const auto v = [&](const char* key) {
    return vec3Text(glm::vec3(d[key][0].get<float>(), d[key][1].get<float>(), d[key][2].get<float>()));
  };
  std::printf("  bounds %s to %s, camera %s\n", v("boundsMin").c_str(), v("boundsMax").c_str(),
              d["camera"].get<std::string>().c_str());
  if (!d["environment"].get<std::string>().empty())
    std::printf("  environment %s (rotation %g degrees, intensity %g)\n",
                d["environment"].get<std::string>().c_str(), d["environmentRotation"].get<float>(),
                d["environmentIntensity"].get<float>());
  if (!d["customAttributes"].empty()) std::printf("  attributes %s\n", d["customAttributes"].dump().c_str());
  if (d["vertexColorMeshes"].get<std::size_t>() > 0)
    std::printf("  vertex colours (COLOR_0) on %zu mesh(es)\n", d["vertexColorMeshes"].get<std::size_t>());
  for (const json& t : d["textures"]) {
    std::string slots;
    for (const json& slot : t["slots"]) slots += (slots.empty() ? "" : ", ") + slot.get<std::string>();
    std::string materials;
    for (const json& m : t["materials"]) materials += (materials.empty() ? "" : ", ") + std::to_string(m.get<int>());
    const std::string name = t["name"].get<std::string>();
    const std::string source = t["source"] == "file" ? t["sourceFile"].get<std::string>()
                               : t["source"] == "dataUri" ? "embedded (data URI)"
                                                          : "embedded (buffer view)";
    std::printf("  texture %d%s: %s (material %s), %dx%d %s %d channel(s), %s, wrap %s/%s, filter %s/%s, %s\n",
                t["index"].get<int>(), name.empty() ? "" : (" '" + name + "'").c_str(), slots.c_str(),
                materials.c_str(), t["width"].get<int>(), t["height"].get<int>(),
                t["mimeType"].get<std::string>().c_str(), t["channels"].get<int>(),
                t["colorSpace"].get<std::string>().c_str(), t["wrapS"].get<std::string>().c_str(),
                t["wrapT"].get<std::string>().c_str(), t["magFilter"].get<std::string>().c_str(),
                t["minFilter"].get<std::string>().c_str(), source.c_str());
  }
}

constexpr const char* kProgram = "iblkit-info";

struct Options {
  std::vector<std::string> files;
  bool asJson = false;
  std::string png;
  iblkit::ToneMapping toneMapping;
};

// Describes every file, each failure on its own line without stopping the others.
int describeFiles(const Options& options) {
  if (!options.png.empty() && (options.files.size() != 1 || !isImage(options.files.front())))
    iblkit::failUsage("--png", "needs exactly one image file");
  iblkit::checkOutputs({options.files.begin(), options.files.end()}, {options.png});
  int status = iblkit::kExitSuccess;
  for (const std::string& name : options.files) {
    try {
      Image pixels;
      const json d = isImage(name)                         ? describeImage(name, &pixels)
                     : std::filesystem::is_directory(name) ? describeBake(name)
                                                           : describeScene(name);
      if (!options.png.empty()) iblkit::writePng(options.png, pixels, options.toneMapping);
      if (options.asJson)
        std::printf("%s\n", d.dump().c_str());
      else
        printText(d);
    } catch (const std::exception& e) {
      iblkit::printError(kProgram, e.what());
      status = iblkit::kExitFailure;
    }
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"What iblkit reads from images, environment maps, glTF models, scenes and bake folders", kProgram};
  app.add_option("files", options.files,
                 "images (.exr .hdr .png), models (.glb .gltf), scenes (.json) or bake folders")
      ->required();
  app.add_flag("--json", options.asJson, "one JSON object per file");
  app.add_option("--png", options.png, "write a tone-mapped PNG preview of the (single) image");
  app.add_option("--exposure", options.toneMapping.exposure, "preview exposure in stops");
  return iblkit::runProgram(app, argc, argv, [&] { return describeFiles(options); });
}
