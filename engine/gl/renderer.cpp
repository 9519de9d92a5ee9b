#include "engine/gl/renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <map>
#include <tuple>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/disk_irradiance.h"
#include "core/error.h"
#include "core/sh_rotation.h"
#include "engine/gl/drawn_lights.h"
#include "engine/gl/light_constants.h"
#include "engine/gl/residual_truncation.h"
#include "engine/gl/render_space.h"
#include "engine/gl/shadow_maps.h"
#include "engine/gl/shadow_mask.h"
#include "engine/gl/gpu_mesh.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/material_textures.h"
#include "engine/gl/shader_program.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {
namespace {

// (cos, sin) of the rotation by -degrees: lookups read the map at R_y(-rotation) d
// (environment_map.h).
glm::vec2 inverseRotation(float degrees) {
  const float radians = -glm::radians(degrees);
  return {std::cos(radians), std::sin(radians)};
}

bool usesIrradianceCube(ShadingMode mode) {
  return mode == ShadingMode::Irradiance || mode == ShadingMode::IrradianceAoBent;
}

// glTF 2.0 section 3.9.5 (doubleSided): false culls back faces; true shades both sides.
void cullFor(const Material& material) {
  if (material.doubleSided)
    glDisable(GL_CULL_FACE);
  else
    glEnable(GL_CULL_FACE);
}

// The alpha mode `mesh` of `material` is drawn with, its texture slots `slots` bound
// (drawnAlphaMode: a MASK or BLEND material whose alpha cannot take a point away, neither by its
// base colour texture nor by the mesh's vertex colours, is drawn opaque).
AlphaMode drawnAlphaMode(const Material& material, unsigned slots, const GpuMesh& mesh) {
  return drawnAlphaMode(material, (slots & kSlotBaseColor) != 0 || mesh.hasVertexAlpha());
}

// Whether every vertex of `mesh` has the same normal and every triangle faces along it (a plane
// such as the scene's ground): its disk lights' irradiance is then one value over the mesh, which
// the vertex shader evaluates as exactly as the pixel would (VERTEX_LIGHTS, lights.glsl).
bool hasConstantNormal(const Mesh& mesh) {
  if (mesh.normals.empty()) return false;
  const glm::vec3 n = mesh.normals.front();
  for (const glm::vec3& m : mesh.normals)
    if (m != n) return false;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
    if (!(glm::dot(glm::cross(b - a, c - a), n) > 0.0f)) return false;
  }
  return true;
}

// The modes that evaluate the material's BRDF lobes (mesh.frag's fullMaterialModel and
// dominantLightsModel); the others read the albedo alone, or the mirror direction.
bool usesMaterialBrdf(ShadingMode mode) {
  return mode == ShadingMode::Full || mode == ShadingMode::FullGltfAo || mode == ShadingMode::FullBothAo ||
         mode == ShadingMode::Lights || mode == ShadingMode::LightsShadowed;
}

}  // namespace

float envRotationFromBake(const EnvironmentStages& env, std::optional<float> degrees) {
  return degrees ? *degrees - env.rotationDegrees : 0.0f;
}

struct Renderer::Impl {
  Scene scene;
  // Where the GPU's positions are relative to (render_space.h): the meshes are uploaded, the
  // shadow maps fitted and the camera placed in it.
  RenderSpace space;
  // Per mesh, RenderSpace::shape: the positions uploaded, and what the shadow maps are fitted to.
  std::vector<Mesh> shapes;
  std::vector<GpuMesh> meshes;
  std::vector<bool> constantNormal;  // hasConstantNormal per mesh
  // mesh.frag specialised per (mode, layer, texture slots read, alpha mode, lights drawn, shadows
  // from the mask, specular layer, lights per vertex, the bake's sun bounce), compiled on first use.
  std::map<std::tuple<ShadingMode, FrameLayer, unsigned, AlphaMode, int, int, bool, bool, bool>, ShaderProgram>
      meshPrograms;
  MaterialTextures materialTextures;
  ShaderProgram skyProgram{"fullscreen.vert", "sky.frag"};
  ShaderProgram presentProgram{"fullscreen.vert", "present.frag"};
  GLuint emptyVertexArray = 0;  // the fullscreen triangle needs a bound VAO but no attributes
  GlTexture latLong, specular, brdfLut, residualSpecular;
  GlTexture irradiance;  // the irradiance modes' cube; id 0 when the stages have none
  // The lights modes' residual cube minus its SH9 (residual_truncation.h); id 0 when the stages have
  // no residual cube.
  GlTexture residualTruncation;
  SphericalHarmonics9 sh9;
  // The lights modes' inputs (drawn_lights.h): the stages without the images.
  EnvironmentStages lightStages;
  // The directions of the suns whose bounced light every mesh carries baked (_SUNBOUNCE, sun i in
  // component i: the first suns of the stages the renderer was made with); empty when some mesh
  // lacks it. The lights modes read it only while the drawn lights are these (bakedSunBounceFor).
  std::vector<glm::vec3> sunBounceDirections;
  // The meshes' SH transfer holds interreflection (a bake with --bounces): mesh.frag's diffuse
  // multi-bounce fit is then off where the transfer lights the surface.
  bool transferInterreflected = false;
  std::unique_ptr<ShadowMaps> shadowMaps;  // made on the first shadowed frame
  std::unique_ptr<ShadowMask> shadowMask;  // made on the first shadowed single-sample frame
  int shadowMaskFrames = 0;
  int groundVisibilityFrames = 0;
  // Per mesh, the ground's triangles split by whether a map covers them (shadowCoverage; empty for
  // the objects, drawn whole), for the maps of shadowMaps->renderCount() == coverageRenders.
  std::vector<ShadowCoverage> shadowCoverage;
  int coverageRenders = -1;
  float rotationDegrees = 0.0f, intensity = 1.0f;
  int specularLevels = 1;
  int specularBaseSize = 0;  // the chain's level 0 face, texels

  // `slots`: the texture slots the variant reads (material.glsl's TEXTURED), those bound for the
  // mesh; a slot not bound costs nothing, and untextured meshes keep the untextured shader.
  // `alphaMode`: MASK and BLEND compile the discard / sample mask in (mesh.frag's ALPHA_MODE), so
  // opaque meshes keep the early depth test.
  // `lightCount`: the lights modes' number of drawn lights (dominant_lights.glsl's LIGHT_COUNT), a
  // constant so that the lights loop unrolls with constant indices (llvmpipe pays a loop over a
  // uniform count and its indexed uniforms per pixel); 0 in the other modes.
  // `fromMask`: where lights-shadowed takes its shadows (shadow.glsl's SHADOW_MASK): 0 the maps,
  // read in the lit pass; 1 its own texel of the frame's shadow mask (shadow_mask.h) at the
  // frame's resolution, 2 a coarser mask upsampled; 3 a planar ground's visibility texture
  // (ShadowMaps::groundVisibility).
  // `specularLayer`: false compiles the specular terms out (hasSpecularLayer, brdf.glsl's
  // SPECULAR_LAYER); the same frame, cheaper, for Lambert materials such as the ground. Only the
  // modes with the material's BRDF have the two variants.
  // `constantNormal`: the mesh's normal is one (hasConstantNormal); with a Lambert material and no
  // normal texture the lights modes take the lights' irradiance from the vertices (VERTEX_LIGHTS).
  // `sunBounce`: the lights modes read the suns' bounce the bake stored for the drawn lights
  // (bakedSunBounceFor; mesh.vert's lightsBounceAt with SUN_BOUNCE), else they estimate it.
  const ShaderProgram& meshProgram(ShadingMode mode, FrameLayer layer, unsigned slots, AlphaMode alphaMode,
                                   int lightCount, int fromMask, bool specularLayer, bool constantNormal,
                                   bool sunBounce) {
    // The feature layers do not depend on the mode: one program each.
    if (layer != FrameLayer::Radiance) mode = ShadingMode::Unlit;
    if (mode != ShadingMode::Lights && mode != ShadingMode::LightsShadowed) lightCount = 0;
    if (mode != ShadingMode::LightsShadowed) fromMask = 0;
    if (lightCount == 0) sunBounce = false;
    if (!usesMaterialBrdf(mode)) specularLayer = true;
    const bool vertexLights = lightCount > 0 && !specularLayer && constantNormal && (slots & kSlotNormal) == 0;
    const auto key =
        std::make_tuple(mode, layer, slots, alphaMode, lightCount, fromMask, specularLayer, vertexLights, sunBounce);
    auto found = meshPrograms.find(key);
    if (found == meshPrograms.end()) {
      const std::string defines = "#define SHADING_MODE " + std::to_string(int(mode)) +
                                  "\n#define FRAME_LAYER " + std::to_string(int(layer)) +
                                  "\n#define TEXTURED " + std::to_string(slots) +
                                  "\n#define ALPHA_MODE " + std::to_string(int(alphaMode)) +
                                  "\n#define LIGHT_COUNT " + std::to_string(lightCount) +
                                  "\n#define SHADOW_MASK " + std::to_string(fromMask) +
                                  "\n#define SPECULAR_LAYER " + std::to_string(int(specularLayer)) +
                                  "\n#define VERTEX_LIGHTS " + std::to_string(int(vertexLights)) +
                                  "\n#define SUN_BOUNCE " + std::to_string(int(sunBounce));
      found = meshPrograms.emplace(key, ShaderProgram("mesh.vert", "mesh.frag", defines)).first;
    }
    return found->second;
  }
};

Renderer::Renderer(const BakedScene& bake, float textureAnisotropy) : impl_(std::make_unique<Impl>()) {
  impl_->scene = bake.scene;
  impl_->space = RenderSpace::of(bake.scene);
  for (const Mesh& mesh : bake.scene.meshes) {
    impl_->shapes.push_back(impl_->space.shape(mesh));
    impl_->meshes.emplace_back(mesh, impl_->shapes.back().positions);
    impl_->constantNormal.push_back(hasConstantNormal(mesh));
  }
  impl_->materialTextures = MaterialTextures(bake.scene, textureAnisotropy);
  impl_->transferInterreflected = bake.transferBounces > 0;
  glCreateVertexArrays(1, &impl_->emptyVertexArray);
  static_assert(kMaxEngineLights <= 4, "_SUNBOUNCE holds four suns");
  const bool sunBounce = std::all_of(impl_->meshes.begin(), impl_->meshes.end(),
                                     [](const GpuMesh& mesh) { return mesh.hasSunBounce(); });
  for (const EnvironmentLight& sun : bake.env.lights.suns)
    if (sunBounce && impl_->sunBounceDirections.size() < std::size_t(kMaxEngineLights))
      impl_->sunBounceDirections.push_back(sun.direction);
  setEnvironment(bake.env);
}

Renderer::~Renderer() {
  if (impl_ && impl_->emptyVertexArray) glDeleteVertexArrays(1, &impl_->emptyVertexArray);
}

void Renderer::setEnvironment(const EnvironmentStages& env) {
  impl_->latLong = uploadLatLong(env.latLong);
  impl_->specular = uploadCubeLevels(env.specular.levels);
  impl_->brdfLut = uploadTable(env.brdfLut);
  impl_->irradiance = env.irradiance.size > 0 ? uploadCubeLevels({env.irradiance}) : GlTexture();
  impl_->sh9 = env.sh9;
  impl_->rotationDegrees = env.rotationDegrees;
  impl_->intensity = env.intensity;
  impl_->specularLevels = int(env.specular.levels.size());
  impl_->specularBaseSize = env.specular.levels.empty() ? 0 : env.specular.levels[0].size;
  // The lights modes read the residual's chain when there is one (drawn_lights.h).
  if (!env.residualSpecular.levels.empty()) impl_->residualSpecular = uploadCubeLevels(env.residualSpecular.levels);
  impl_->residualTruncation = !env.residualSpecular.levels.empty() && env.residualIrradiance.size > 0
                                  ? uploadCubeLevels({residualTruncationCube(env.residualIrradiance, env.residualSh9)})
                                  : GlTexture();
  EnvironmentStages& stages = impl_->lightStages;
  stages.sh9 = env.sh9;
  stages.lights = env.lights;
  stages.residualSh9 = env.residualSh9;
  stages.residualSpecular.levels.clear();
  stages.residualSpecular.roughness = env.residualSpecular.roughness;
  // Only whether it exists matters to drawnLights; one empty level stands for the uploaded chain.
  if (!env.residualSpecular.levels.empty()) stages.residualSpecular.levels.resize(1);
  invalidateShadowMaps();
}

const EnvironmentStages& Renderer::lightStages() const { return impl_->lightStages; }

int Renderer::shadowMaskFrames() const { return impl_->shadowMaskFrames; }
int Renderer::groundVisibilityFrames() const { return impl_->groundVisibilityFrames; }

int Renderer::shadowMapRenders() const { return impl_->shadowMaps ? impl_->shadowMaps->renderCount() : 0; }

void Renderer::invalidateShadowMaps() {
  if (impl_->shadowMaps) impl_->shadowMaps->update({}, {}, {});
}

void Renderer::setMaterial(int materialIndex, const Material& material) {
  impl_->scene.materials.at(std::size_t(materialIndex)) = material;
}

const std::vector<Material>& Renderer::materials() const { return impl_->scene.materials; }

const Scene& Renderer::scene() const { return impl_->scene; }

float Renderer::textureAnisotropy() const { return impl_->materialTextures.anisotropy(); }

void Renderer::render(const Camera& camera, const FrameSettings& settings, GLuint framebuffer, int width,
                      int height) {
  Impl& r = *impl_;
  if (usesIrradianceCube(settings.mode) && settings.layer == FrameLayer::Radiance && r.irradiance.id() == 0)
    throw Error(std::string(shadingModeName(settings.mode)) +
                " mode: the environment stages have no irradiance cube (env/irradiance.exr)");
  // The lights modes: lights-shadowed without shadows is lights. The shadow maps are rendered here,
  // before the frame's target is bound, and only when a light's direction changed.
  const bool lightsMode = settings.mode == ShadingMode::Lights || settings.mode == ShadingMode::LightsShadowed;
  const ShadingMode mode =
      settings.mode == ShadingMode::LightsShadowed && !settings.shadows ? ShadingMode::Lights : settings.mode;
  DrawnLights drawn;
  // The drawn lights' directions and disks, as the shadow maps and light_directions.glsl take them.
  std::vector<ShadowLight> shadowLights;
  if (lightsMode && settings.layer == FrameLayer::Radiance) {
    drawn = drawnLights(r.lightStages, settings.lightCount, settings.envRotationDegrees);
    for (const EnvironmentLight& light : drawn.lights)
      shadowLights.push_back({light.direction, light.angularRadius});
    if (mode == ShadingMode::LightsShadowed) {
      if (!r.shadowMaps) r.shadowMaps = std::make_unique<ShadowMaps>(kShadowMapSize);
      r.shadowMaps->update(r.shapes, r.meshes, shadowLights);
      r.shadowMaps->bind();
      if (r.coverageRenders != r.shadowMaps->renderCount()) {
        r.shadowCoverage.assign(r.scene.meshes.size(), {});
        for (std::size_t i = 0; i < r.scene.meshes.size(); ++i)
          if (r.shapes[i].isGround) r.shadowCoverage[i] = shadowCoverage(r.shapes[i], r.shadowMaps->frames());
        r.coverageRenders = r.shadowMaps->renderCount();
      }
    }
    glBindTextureUnit(kTextureUnitResidualSpecular, drawn.residualChain ? r.residualSpecular.id() : r.specular.id());
    glBindTextureUnit(kTextureUnitResidualIrradiance, r.residualTruncation.id());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  GLint samples = 1;
  glGetIntegerv(GL_SAMPLES, &samples);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  // Everything the GPU draws is in render space (render_space.h): the camera too.
  const glm::mat4 viewProjection =
      camera.projectionMatrix(float(width) / float(height)) * camera.viewMatrix(r.space.origin);
  const glm::vec2 latLongRotation = inverseRotation(r.rotationDegrees + settings.envRotationDegrees);
  // SH9 radiance turned by the extra rotation (the scene's is in the baked coefficients).
  const SphericalHarmonics9 sh =
      settings.envRotationDegrees == 0.0f ? r.sh9 : rotateShAboutY(r.sh9, settings.envRotationDegrees);
  // The residual cube's correction of the residual SH9 (mesh.vert residualIrradianceAt, residual_truncation.h),
  // turned by the extra rotation like the specular chain; off without a cube (a bake from before
  // it) or without a residual chain.
  const bool cubeCorrection = lightsMode && drawn.residualChain && r.residualTruncation.id() != 0;
  const bool sunBounce = lightsMode && bakedSunBounceFor(r.sunBounceDirections, drawn.lights);
  auto setFrameUniforms = [&](const ShaderProgram& program) {
    program.set("framebufferSamples", int(samples));
    program.set("viewProjection", viewProjection);
    program.set("cameraPosition", r.space.fromWorld(camera.position));
    program.setArray("shRadiance", sh.coefficients.data(), kShCoefficients);
    program.set("latLongRotation", latLongRotation);
    program.set("latLongIntensity", r.intensity);
    program.set("specularRotation", inverseRotation(settings.envRotationDegrees));
    program.set("specularLevels", float(r.specularLevels));
    program.set("transferInterreflected", int(r.transferInterreflected));
    if (!lightsMode) return;
    setLightDirections(program, shadowLights);
    for (std::size_t i = 0; i < drawn.lights.size(); ++i) {
      const EnvironmentLight& light = drawn.lights[i];
      program.set(uniformElement("lightRadiance", i).c_str(), light.radiance);
      program.set(uniformElement("lightMirrorEdgeCos", i).c_str(),
                  glm::vec2(std::cos(1.1f * light.angularRadius), std::cos(0.9f * light.angularRadius)));
      // A near-mirror reflects the light's own texels of the chain's level 0 where its disk is wider
      // than one of those texels (90 degrees / face size), the uniform disk below that (the
      // level's texels would blur it more than its shape matters).
      const float window = glm::radians(1.0f);
      const float texel = glm::half_pi<float>() / float(std::max(r.specularBaseSize, 1));
      program.set(uniformElement("lightTexelWindowCos", i).c_str(),
                  glm::vec2(std::cos(std::min(2.0f * light.angularRadius + window, glm::pi<float>())),
                            std::cos(std::min(1.5f * light.angularRadius + window, glm::pi<float>()))));
      program.set(uniformElement("lightMirrorTexels", i).c_str(),
                  drawn.residualChain && light.angularRadius > texel ? 1.0f : 0.0f);
      program.set(uniformElement("lightIrradianceUp", i).c_str(),
                  light.radiance * uniformDiskIrradiance(light.direction.y, light.angularRadius));
      program.set(uniformElement("lightIrradiance", i).c_str(), light.irradiance);
    }
    program.setArray("residualShRadiance", drawn.residualSh9.coefficients.data(), kShCoefficients);
    program.set("residualCubeCorrection", cubeCorrection ? 1 : 0);
    if (mode == ShadingMode::LightsShadowed) r.shadowMaps->setUniforms(program);
  };
  // On a single-sample target the shadows come from the frame's mask (shadow_mask.h), drawn over
  // the receivers the lit pass draws with the shadowed program: every mesh drawn opaque
  // (drawnAlphaMode), the ground by its covered triangles only (below). A MASK or BLEND mesh whose
  // alpha can drop a point keeps the lookups in the lit pass (the surface pass has no alpha test).
  const bool fromMask = mode == ShadingMode::LightsShadowed && settings.layer == FrameLayer::Radiance &&
                        settings.shadowMask && samples <= 1 && !drawn.lights.empty();
  // The ground's shadows from its visibility texture (ShadowMaps::groundVisibility): the ground is
  // left out of the mask's surfaces and drawn with SHADOW_MASK 3.
  const bool groundFromMaps = mode == ShadingMode::LightsShadowed && settings.layer == FrameLayer::Radiance &&
                              settings.groundVisibility && !drawn.lights.empty() && r.shadowMaps &&
                              r.shadowMaps->groundVisibility();
  if (groundFromMaps) ++r.groundVisibilityFrames;
  if (fromMask) {
    ++r.shadowMaskFrames;
    if (!r.shadowMask) r.shadowMask = std::make_unique<ShadowMask>();
    r.shadowMask->beginSurfaces(width, height, settings.shadowMaskDivisor);
    r.shadowMask->surfaceProgram().set("viewProjection", viewProjection);
    glCullFace(GL_BACK);
    for (std::size_t i = 0; i < r.meshes.size(); ++i) {
      const Mesh& mesh = r.scene.meshes[i];
      const Material& material = r.scene.materials.at(std::size_t(mesh.material));
      if (drawnAlphaMode(material, r.materialTextures.boundSlots(material, settings.textureSlots), r.meshes[i]) !=
          AlphaMode::Opaque)
        continue;
      // The ground reads its own visibilities (ShadowMaps::groundVisibility), not the mask's.
      if (mesh.isGround && groundFromMaps) continue;
      cullFor(material);
      if (mesh.isGround && i < r.shadowCoverage.size())
        r.meshes[i].draw(r.shadowCoverage[i].covered);
      else
        r.meshes[i].draw();
    }
    glDisable(GL_CULL_FACE);
    const ShaderProgram& maskProgram = r.shadowMask->maskProgram(int(drawn.lights.size()));
    setFrameUniforms(maskProgram);
    r.shadowMask->computeMask(maskProgram, r.emptyVertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  }
  // How the lit pass reads the mask (meshProgram's fromMask), and the mask's pixels per frame pixel.
  const int maskReading = !fromMask ? 0 : settings.shadowMaskDivisor == 1 ? 1 : 2;
  const glm::vec2 maskScale = fromMask ? glm::vec2(r.shadowMask->scaleX(), r.shadowMask->scaleY()) : glm::vec2(1.0f);
  glViewport(0, 0, width, height);
  if (settings.sampleShading) {
    glEnable(GL_SAMPLE_SHADING);
    glMinSampleShading(1.0f);
  } else {
    glDisable(GL_SAMPLE_SHADING);
  }
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // The samplers are declared with these units (layout(binding), texture_unit.h).
  glBindTextureUnit(kTextureUnitLatLong, r.latLong.id());
  glBindTextureUnit(kTextureUnitSpecular, r.specular.id());
  glBindTextureUnit(kTextureUnitBrdfLut, r.brdfLut.id());
  glBindTextureUnit(kTextureUnitIrradiance, r.irradiance.id());

  if (settings.drawSky && settings.layer == FrameLayer::Radiance) {
    const ShaderProgram& sky = r.skyProgram;
    sky.set("inverseViewProjection", glm::inverse(viewProjection));
    sky.set("latLongRotation", latLongRotation);
    sky.set("latLongIntensity", r.intensity);
    sky.use();
    glBindVertexArray(r.emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glCullFace(GL_BACK);
  const ShaderProgram* current = nullptr;
  std::vector<const ShaderProgram*> prepared;  // programs whose frame uniforms are set
  for (std::size_t i = 0; i < r.meshes.size(); ++i) {
    const Mesh& mesh = r.scene.meshes[i];
    const Material& material = r.scene.materials.at(std::size_t(mesh.material));
    // The slots bound (present, switched on, uploaded) choose the program variant.
    const unsigned slots = r.materialTextures.bind(material, settings.textureSlots);
    const AlphaMode alphaMode = drawnAlphaMode(material, slots, r.meshes[i]);
    // Where the shadows come from: the ground's own visibilities (3), the mask (maskReading) for
    // what the surface pass drew, else the maps read in the lit pass (0).
    const int shadowSource = mesh.isGround && groundFromMaps ? 3
                             : fromMask && alphaMode == AlphaMode::Opaque ? maskReading
                                                                          : 0;
    const auto use = [&](ShadingMode programMode) -> const ShaderProgram& {
      const ShaderProgram& program =
          r.meshProgram(programMode, settings.layer, slots, alphaMode, int(drawn.lights.size()), shadowSource,
                        hasSpecularLayer(material), r.constantNormal[i], sunBounce);
      if (std::find(prepared.begin(), prepared.end(), &program) == prepared.end()) {
        setFrameUniforms(program);
        program.set("shadowMaskScale", maskScale);
        prepared.push_back(&program);
      }
      if (current != &program) {
        program.use();
        current = &program;
      }
      program.set("isGround", int(mesh.isGround));
      setMaterialUniforms(program, material, slots);
      return program;
    };
    cullFor(material);
    // The ground outside every map is lit by all lights (the maps' border): drawn by the lights
    // program, without the shadow lookups, which every pixel would otherwise pay (llvmpipe runs
    // both sides of a branch).
    const bool splitGround = mode == ShadingMode::LightsShadowed && settings.layer == FrameLayer::Radiance &&
                             mesh.isGround && i < r.shadowCoverage.size();
    if (splitGround) {
      use(ShadingMode::LightsShadowed);
      r.meshes[i].draw(r.shadowCoverage[i].covered);
      use(ShadingMode::Lights);
      r.meshes[i].draw(r.shadowCoverage[i].uncovered);
    } else {
      use(mode);
      r.meshes[i].draw();
    }
  }
  glDisable(GL_CULL_FACE);
  for (GLuint unit = kTextureUnitBaseColor; unit <= kTextureUnitEmissive; ++unit) glBindSampler(unit, 0);
  glBindSampler(kTextureUnitShadowDepth, 0);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
}

void Renderer::presentToneMapped(GLuint texture, const FrameSettings& settings, int x, int y, int w, int h) {
  Impl& r = *impl_;
  glViewport(x, y, w, h);
  glBindTextureUnit(kTextureUnitPresent, texture);
  r.presentProgram.set("exposure", settings.exposure);
  r.presentProgram.set("curve", int(settings.curve));
  r.presentProgram.use();
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(r.emptyVertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace iblkit
