#include "engine/baked/baked_scene.h"

#include "baker/environment_sh.h"

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "baker/environment_sh.h"
#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "core/environment_map_file.h"
#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void requireFile(const fs::path& file) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) fail(file, "missing (incomplete bake folder?)");
}

json readJson(const fs::path& file) {
  requireFile(file);
  std::ifstream stream(file);
  try {
    return json::parse(stream);
  } catch (const json::exception& e) {
    fail(file, std::string("not valid JSON: ") + e.what());
  }
}

// Every mesh of a baked scene needs the visibility attributes, with one value per vertex.
void requireBakedAttributes(const Scene& scene, const fs::path& file) {
  const std::pair<const char*, int> expected[] = {
      {kAmbientOcclusionAttribute, 1}, {kBentNormalAttribute, 3},   {kBentLengthAttribute, 1},
      {kTransferAttributes[0], 3},     {kTransferAttributes[1], 3}, {kTransferAttributes[2], 3}};
  for (const Mesh& mesh : scene.meshes)
    for (const auto& [name, components] : expected) {
      const auto found = mesh.attributes.find(name);
      if (found == mesh.attributes.end() || found->second.componentCount != components ||
          found->second.data.size() != std::size_t(components) * mesh.vertexCount())
        fail(file,
             "mesh '" + mesh.name + "' has no baked " + name + " attribute (not an iblkit-bake scene?)");
    }
}

// env/specular.exr: the first log2(W) + 1 levels are the cube chain, one per roughness in the
// "iblkit:roughnessPerLevel" attribute (docs/prefilter.md).
SpecularCube readSpecularExr(const fs::path& file) {
  requireFile(file);
  ExrInfo info;
  const std::vector<Image> strips = readExrLevels(file, &info);
  std::string roughnessText;
  for (const auto& [name, value] : info.stringAttributes)
    if (name == "iblkit:roughnessPerLevel") roughnessText = value;
  SpecularCube cube;
  std::istringstream values(roughnessText);
  for (float r; values >> r;) cube.roughness.push_back(r);
  if (cube.roughness.empty()) fail(file, "no iblkit:roughnessPerLevel attribute (not an iblkit-bake cube)");
  if (cube.roughness.size() > strips.size())
    fail(file, std::to_string(cube.roughness.size()) + " roughness levels listed but only " +
                   std::to_string(strips.size()) + " mip levels stored");
  for (std::size_t level = 0; level < cube.roughness.size(); ++level)
    cube.levels.push_back(cubeFromExrStrip(strips[level], file));
  if (cube.levels.back().size != 1) fail(file, "the specular chain does not end at 1 x 1 faces");
  return cube;
}

BakedScene readBakeFolder(const fs::path& folder) {
  const fs::path bakeJson = folder / "bake.json";
  std::error_code error;
  if (!fs::is_directory(folder, error)) fail(folder, "no such bake folder");
  const json record = readJson(bakeJson);
  const std::string version = record.value("version", std::string());
  if (version != kBakeVersion)
    fail(bakeJson, "version '" + version + "' is not supported (expected '" + kBakeVersion + "')");

  BakedScene bake;
  EnvironmentStages& env = bake.env;
  try {
    const json& environment = record.at("inputs").at("environment");
    if (environment.is_null()) fail(bakeJson, "the bake has no environment stages (bake with --env)");
    const json& parameters = record.at("parameters");
    // Bakes record an absolute path; a relative one (hand-written bake.json) is relative to the bake.
    fs::path environmentFile = environment.get<std::string>();
    if (environmentFile.is_relative()) environmentFile = folder / environmentFile;
    env.rotationDegrees = parameters.at("environment_rotation_degrees").get<float>();
    env.intensity = parameters.at("environment_intensity").get<float>();
    const ProbeFormat format = parseProbeFormat(parameters.value("env_format", std::string("latlong")));
    requireFile(environmentFile);
    env.latLong = loadEnvironmentMap(environmentFile, format).image();
  } catch (const json::exception& e) {
    fail(bakeJson, std::string("missing environment record: ") + e.what());
  }
  const fs::path sceneFile = folder / "scene.glb";
  requireFile(sceneFile);
  bake.scene = loadScene(sceneFile);
  requireBakedAttributes(bake.scene, sceneFile);
  requireFile(folder / "env" / "sh9.json");
  env.sh9 = readSh9Json(folder / "env" / "sh9.json", &env.shWindowCutoff);
  env.specular = readSpecularExr(folder / "env" / "specular.exr");
  const fs::path lut = folder / "env" / "brdf_lut.exr";
  requireFile(lut);
  env.brdfLut = readExr(lut);
  return bake;
}

BakedScene bakeInMemory(const fs::path& sceneFile, const LoadBakeOptions& options) {
  BakedScene bake;
  bake.scene = loadScene(sceneFile);
  bake.bakedInMemory = true;
  const fs::path environmentFile =
      options.environment.empty() ? bake.scene.environment.file : options.environment;
  if (environmentFile.empty())
    fail(sceneFile, "names no environment map (give one, or bake it with iblkit-bake --env)");
  requireFile(environmentFile);
  EnvironmentMap environment = loadEnvironmentMap(environmentFile);
  environment.setRotationDegrees(bake.scene.environment.rotationDegrees);
  environment.setIntensity(bake.scene.environment.intensity);
  std::cerr << sceneFile.string() << ": a scene, not a bake folder: baking it in memory (" << options.aoRays
            << " visibility rays per vertex)\n";
  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  attachVisibilityAttributes(bake.scene.meshes, bakeVertexVisibility(bake.scene.meshes, settings));
  bake.env = prepareEnvironment(environment);
  return bake;
}

}  // namespace

BakedScene loadBake(const fs::path& dirOrScene, const LoadBakeOptions& options) {
  std::error_code error;
  if (fs::is_regular_file(dirOrScene, error)) return bakeInMemory(dirOrScene, options);
  return readBakeFolder(dirOrScene);
}

}  // namespace iblkit
