#pragma once
// Shadow maps of the engine's disk lights (docs/engine.md "Shadows"): per light one square map of
// kShadowMapSize texels, a layer of two texture arrays rendered together: the depth
// (GL_DEPTH_COMPONENT32F, the depth test's buffer) and its exponential moments (GL_RG32F with a
// full mip chain: (d, exp(kShadowExponent (d - 1))) per texel, box-filtered down by
// glGenerateTextureMipmap), which shadow.glsl filters with one trilinear tap per pass. The
// projection is orthographic along the light, fitted tightly to what can cast a shadow: the
// objects (every mesh but the ground), with the ground's depth where it is under them. The lights
// are distant and the scene is static, so the maps depend only on the lights: update() renders
// them again only when a direction or an angular radius changed (a new environment, K, an
// environment rotation), never because the camera moved.
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <map>
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
  // A receiver plane's normal g (world) -> h, with |h.xy| / |h.z| the world slope of the map's
  // depth along that plane (shadow.glsl's plane correction).
  glm::mat3 slopeFromNormal{1.0f};
};

// What a shadow map depends on: the unit direction towards the light and its angular radius.
struct ShadowLight {
  glm::vec3 towardsLight{0.0f, 1.0f, 0.0f};
  float angularRadius = 0.0f;
  bool operator==(const ShadowLight&) const = default;
};

// Sets light_directions.glsl's uniforms of `program` for `lights`: lightDirection[i], the unit
// direction towards light i, and lightCosSin[i], the cos and sin of its angular radius. The lit
// pass (renderer.cpp) and the ground's visibility pass (ShadowMaps) set them through this one
// function, so both see each light alike.
void setLightDirections(const ShaderProgram& program, const std::vector<ShadowLight>& lights);

// The tight orthographic frame along `light.towardsLight` for a `size`-texel map:
// - across the light (u, v): the objects' vertices (the meshes not marked isGround; all meshes when
//   there is none), grown on each side by the widest blocker search a receiver in the map makes
//   (its depth range times tan of the angular radius) plus two texels. Outside it no object can
//   shadow anything: shadow.glsl reads the border there, lit.
// - along it (depth): the objects' vertices and the ground's points under the map's rectangle (a
//   planar ground mesh's plane at the rectangle's corners; a ground that is not planar, or seen
//   edge-on: all its vertices), 1% of margin at both ends. The ground further away is not drawn.
//   Depth is the distance towards the light from the ground's plane where the ground meshes lie on
//   one plane (the light more than kShadowGroundShearMinCos off it), so that the ground has one
//   depth across the map; else from a plane across the light. Either way, at a given (u, v) two
//   points' depths differ by their distance along the light over the depth range.
// Empty meshes: a unit box at the origin.
ShadowFrame fitShadowFrame(const std::vector<Mesh>& meshes, const ShadowLight& light, int size);

// A mesh's triangles split by whether a shadow map can darken them (docs/engine.md "Shadows",
// "Receivers"): `covered` holds those whose (u, v) box in some frame overlaps the map's square,
// `uncovered` the rest, which shadow.glsl would read as lit (the map's border), each as runs of
// consecutive triangles in index order. Every triangle is in exactly one of them. The renderer
// draws the uncovered runs of the ground without the shadow lookups.
struct ShadowCoverage {
  std::vector<TriangleRun> covered, uncovered;
};
ShadowCoverage shadowCoverage(const Mesh& mesh, const std::vector<ShadowFrame>& frames);

// The planar ground's visibility of every light (docs/engine.md "Shadows", "The ground's
// visibility"): an RGBA8 texture over the ground's plane, light i's visibility in component i,
// computed with the maps (shadow_ground.frag: shadow.glsl's shadowVisibilities at each texel's
// point of the plane) and read by the lit pass with one bilinear tap a ground pixel
// (groundShadowVisibilities). It covers the maps' squares seen along their lights on the plane
// (outside them no light is shadowed), cut to the ground meshes, in texels of the finest map's
// size, at most kGroundVisibilityMaxSize along the longer side.
inline constexpr int kGroundVisibilityMaxSize = 1024;
struct GroundVisibilityFrame {
  int width = 0, height = 0;  // texels; 0 where there is no ground visibility
  glm::vec3 origin{0.0f};     // the plane's point at the texture's corner (0, 0)
  glm::vec3 stepU{0.0f}, stepV{0.0f};  // a texel's sides in world space
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // the plane's
  glm::vec3 uFromWorld{0.0f}, vFromWorld{0.0f};  // (u, v) = (uFromWorld.(p - origin), vFromWorld.(p - origin))
  bool valid() const { return width > 0 && height > 0; }
};
// The frame for `frames` of `lights`: none (width 0) without objects, where the ground meshes do
// not lie on one plane, or where the maps' squares miss the ground.
GroundVisibilityFrame fitGroundVisibility(const std::vector<Mesh>& meshes, const std::vector<ShadowLight>& lights,
                                          const std::vector<ShadowFrame>& frames, int maxSize);

class ShadowMaps {
 public:
  // `size`: the side of each map in texels. Needs a current OpenGL 4.5 context.
  explicit ShadowMaps(int size);
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // Makes the maps those of `lights`: fits each frame, renders `gpuMeshes` (drawn like `meshes`,
  // both faces, opaque) into its layer, builds the moments' mip chain and the ground's visibility
  // (GroundVisibilityFrame, where there is one), only when the lights differ from the last call's. Leaves framebuffer 0 bound, the viewport to the caller (render()
  // sets its own), program and vertex array 0, depth test off.
  void update(const std::vector<Mesh>& meshes, const std::vector<GpuMesh>& gpuMeshes,
              const std::vector<ShadowLight>& lights);

  // Binds the moments to kTextureUnitShadowDepth (trilinear; outside the map they read as the far
  // plane, lit) and the ground's visibility to kTextureUnitShadowGround (bilinear).
  void bind() const;
  // Sets shadow.glsl's uniforms for the current frames.
  void setUniforms(const ShaderProgram& program) const;

  // Whether the maps come with the ground's visibility of each light (kTextureUnitShadowGround;
  // shadow.glsl's groundShadowVisibilities): where the ground meshes lie on one plane and there
  // are objects to cast shadows onto it.
  bool groundVisibility() const { return ground_.valid(); }
  const GroundVisibilityFrame& groundFrame() const { return ground_; }
  const std::vector<ShadowFrame>& frames() const { return frames_; }
  int size() const { return size_; }
  // How many times the maps were rendered (each update that changed a light): a camera move
  // renders none.
  int renderCount() const { return renderCount_; }

 private:
  int size_;
  int layers_ = 0;  // allocated layers of the texture arrays
  GlTexture depth_, moments_;  // the depth test's buffer, the moments
  void renderGroundVisibility(const std::vector<Mesh>& meshes, const std::vector<ShadowLight>& lights);
  GroundVisibilityFrame ground_;
  GlTexture groundVisibility_;  // GL_RGBA8, groundWidth_ x groundHeight_
  int groundWidth_ = 0, groundHeight_ = 0;
  GLuint framebuffer_ = 0, momentsSampler_ = 0, groundSampler_ = 0, emptyVertexArray_ = 0;
  ShaderProgram depthProgram_{"shadow_depth.vert", "shadow_depth.frag"};
  std::map<int, ShaderProgram> groundPrograms_;  // shadow_ground.frag per light count
  std::vector<ShadowLight> lights_;
  std::vector<ShadowFrame> frames_;
  int renderCount_ = 0;
};

}  // namespace iblkit
