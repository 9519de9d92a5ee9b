#pragma once
// Shadow maps of the engine's disk lights (docs/engine.md "Shadows"): per light one square depth
// map of kShadowMapSize texels (a layer of one GL_DEPTH_COMPONENT32F texture array), rendered with
// an orthographic projection along the light fitted tightly to the scene's vertices, the ground
// included. The lights are distant and the scene is static, so the maps depend only on the light
// directions: update() renders them again only when a direction changed (a new environment, K, an
// environment rotation), never because the camera moved.
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include "core/mesh.h"
#include "engine/gl/gpu_mesh.h"
#include "engine/gl/gpu_textures.h"
#include "engine/gl/shader_program.h"

namespace iblkit {

// Light i's orthographic frame: world -> (u, v, depth) in [0, 1]^3, depth 0 towards the light.
struct ShadowFrame {
  glm::mat4 shadowFromWorld{1.0f};
  glm::vec3 right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};  // the map's u and v axes in world space
  // World size of the map along right and up, its depth range, and its texel's side (the larger).
  glm::vec4 extent{1.0f};
};

// The tight orthographic frame along `towardsLight` (unit, world) holding `meshes`' vertices, with
// a margin of two texels of a `size`-texel map on each side (so that PCF taps at the border read
// real depths). Empty meshes: a unit box at the origin.
ShadowFrame fitShadowFrame(const std::vector<Mesh>& meshes, const glm::vec3& towardsLight, int size);

// n points on the unit disk, uniform in area: the golden-angle spiral of Vogel 1979 (tap i at
// radius sqrt((i + 0.5) / n), angle i x 2.39996 radians), the shadow lookups' taps.
std::vector<glm::vec2> vogelDiskTaps(int n);

class ShadowMaps {
 public:
  // `size`: the side of each map in texels. Needs a current OpenGL 4.5 context.
  explicit ShadowMaps(int size);
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Makes the maps those of `directions` (unit, towards each light): fits each frame and renders
  // the depth of `gpuMeshes` (drawn like `meshes`, both faces, opaque) into its layer, only when
  // the directions differ from the last call's. Leaves framebuffer 0 bound, the viewport to the
  // caller (render() sets its own), program and vertex array 0, depth test off.
  void update(const std::vector<Mesh>& meshes, const std::vector<GpuMesh>& gpuMeshes,
              const std::vector<glm::vec3>& directions);

  // Binds the maps to kTextureUnitShadowDepth (raw depths, nearest) and kTextureUnitShadowCompare
  // (GL_COMPARE_REF_TO_TEXTURE, bilinear: 2 x 2 PCF per tap), outside the map: depth 1 (lit).
  void bind() const;
  // Sets shadow.glsl's uniforms for the current frames.
  void setUniforms(const ShaderProgram& program) const;

  const std::vector<ShadowFrame>& frames() const { return frames_; }
  int size() const { return size_; }
  // How many times the maps were rendered (each update that changed a direction): a camera move
  // renders none.
  int renderCount() const { return renderCount_; }

 private:
  int size_;
  int layers_ = 0;  // allocated layers of the texture array
  GlTexture depth_;
  GLuint framebuffer_ = 0, rawSampler_ = 0, compareSampler_ = 0;
  ShaderProgram depthProgram_{"shadow_depth.vert", "shadow_depth.frag"};
  std::vector<glm::vec3> directions_;
  std::vector<ShadowFrame> frames_;
  int renderCount_ = 0;
};

}  // namespace iblkit
