#pragma once
// The real-time image-based-lighting renderer (docs/engine.md): draws a baked scene with one of
// the shading modes into a float framebuffer, in linear radiance, with the core camera so that a
// frame lines up pixel for pixel with iblkit-trace's image of the same scene.
#include <epoxy/gl.h>

#include <memory>
#include <optional>
#include <vector>

#include "bakefile/bake_folder.h"
#include "core/camera.h"
#include "core/material.h"
#include "core/texture.h"
#include "core/tone_curve.h"
#include "engine/gl/frame_layer.h"
#include "engine/gl/shading_mode.h"

namespace iblkit {

struct FrameSettings {
  ShadingMode mode = ShadingMode::Full;
  float exposure = 0.0f;                    // stops; presentToneMapped only (render writes linear radiance)
  ToneCurve curve = ToneCurve::AcesFitted;  // presentToneMapped only
  // Extra environment rotation about +Y (degrees, environment_map.h's sense), on top of the
  // bake's, applied to every lookup (sky, mirror, SH9, PRT, specular cube): the stages are baked
  // at one rotation and turned here rather than baked again. envRotationFromBake gives it.
  float envRotationDegrees = 0.0f;
  bool drawSky = true;  // false: the background is black with alpha 0
  FrameLayer layer = FrameLayer::Radiance;
  // Shade every sample of a multisampled target (supersampling): the shading is then averaged
  // over the pixel like the reference's pixel filter does, not only the edges. N times the cost.
  bool sampleShading = false;
  // The material texture slots used (TextureSlot bits, core/texture.h): a slot switched off reads
  // as "no texture" (the factor alone), to see what each contributes (the viewer's panel,
  // iblkit-view --texture-slots, the benchmarks).
  unsigned textureSlots = kAllTextureSlots;
  // The lights modes (docs/engine.md "Lights"): how many of the environment's suns are drawn as
  // lights, K (< 0: all, at most kMaxEngineLights; the others go back into the residual's SH9),
  // and whether lights-shadowed shadows them (false: it draws as lights).
  int lightCount = -1;
  bool shadows = true;
  // lights-shadowed on a single-sample target: the shadows computed once per pixel in a screen-space
  // pass (shadow_mask.h) rather than in the lit pass; the same frame to the mask's precision (16
  // bits at the frame's resolution, 8 at a coarser one; shadow_mask.frag's MASK_BITS), faster
  // on a software rasteriser (docs/engine.md "Shadows"). Multisampled targets always shadow in the
  // lit pass.
  bool shadowMask = true;
  // The mask's pixel, in frame pixels on a side: 1 (the lit pass's own visibilities) or 2 (a
  // quarter of the lookups, upsampled with the mask's depths; penumbrae interpolated over 2
  // pixels, shadow_mask.h).
  int shadowMaskDivisor = 2;
  // lights-shadowed on a planar ground: the ground's shadows read from the texture of the ground's
  // visibility, computed with the maps (one tap a pixel; shadow_maps.h GroundVisibilityFrame)
  // rather than per pixel (the mask or the lit pass). Off: the ground's pixels as the objects'.
  bool groundVisibility = true;
};

// The envRotationDegrees that shows the environment at the absolute rotation `degrees` about +Y
// (--env-rotation, docs/conventions.md): the turn from the rotation `env` was baked at; 0 when
// `degrees` is unset (the bake's own rotation).
float envRotationFromBake(const EnvironmentStages& env, std::optional<float> degrees);

// The anisotropy the renderer's trilinear samplers ask for (where the driver offers it).
inline constexpr float kDefaultTextureAnisotropy = 16.0f;

class Renderer {
 public:
  // Uploads the scene's meshes (with their baked attributes), material textures (their core mip
  // chains, MaterialTextures; trilinear samplers with up to 16x anisotropy where the driver offers
  // it) and environment stages. Needs a
  // current OpenGL 4.5 core context (HeadlessContext or a window's); the Renderer must be
  // destroyed while that context is still current. Throws Error for shader build failures.
  // `textureAnisotropy` caps the trilinear samplers' anisotropy (1: isotropic, as the reference's
  // footprint rule is; clamped to the driver's maximum).
  explicit Renderer(const BakedScene& bake, float textureAnisotropy = kDefaultTextureAnisotropy);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Replaces the environment (sky, SH9, specular chain, DFG table, irradiance cube when it has
  // one); e.g. from computeEnvironmentStages.
  // PRT keeps working: the transfer vectors do not depend on the lighting.
  void setEnvironment(const EnvironmentStages& env);
  // Overrides material `materialIndex` (an index into materials()). Throws std::out_of_range.
  void setMaterial(int materialIndex, const Material& material);
  const std::vector<Material>& materials() const;
  // The scene as given to the constructor (its camera, bounds, image size).
  const Scene& scene() const;
  // The anisotropy the trilinear texture samplers use (1 where the driver offers none).
  float textureAnisotropy() const;
  // What the lights modes draw from the environment given to the constructor or the last
  // setEnvironment (drawn_lights.h): its sh9, lights and residualSh9; residualSpecular has one
  // empty level when the residual's chain was uploaded, none otherwise; no images.
  const EnvironmentStages& lightStages() const;
  // How many times the shadow maps were rendered (ShadowMaps::renderCount; 0 before the first
  // shadowed frame), and their side in texels.
  int shadowMapRenders() const;
  // How many frames took their shadows from the screen-space mask (FrameSettings::shadowMask).
  int shadowMaskFrames() const;
  // How many frames read the ground's shadows from its visibility texture
  // (FrameSettings::groundVisibility; where there is a planar ground and objects).
  int groundVisibilityFrames() const;
  // Drops the shadow maps, so that the next shadowed frame renders them again (the benchmark of
  // their cost; a new environment does it by itself).
  void invalidateShadowMaps();

  // Renders into `framebuffer` (0 = the default one) over the viewport (0, 0, width, height): clears
  // colour and depth, draws the sky (if settings.drawSky) and every mesh. Afterwards `framebuffer`
  // stays bound and seamless cube filtering on; program, vertex array and depth test are back to
  // 0 / off. Throws Error for an irradiance mode when the environment has no irradiance cube.
  void render(const Camera& camera, const FrameSettings& settings, GLuint framebuffer, int width, int height);

  // Draws the linear float 2D `texture` into the viewport (x, y, w, h) of the currently bound
  // draw framebuffer, tone-mapped with the core curve: sRGB_OETF(curve(radiance 2^exposure)), as
  // toneMap (tone_curve.h) computes it; writes display values (no GL_FRAMEBUFFER_SRGB needed).
  void presentToneMapped(GLuint texture, const FrameSettings& settings, int x, int y, int w, int h);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace iblkit
