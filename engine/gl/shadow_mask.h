#pragma once
// The frame's shadow mask (docs/engine.md "Shadows"): the lights-shadowed mode's visibilities
// computed once per pixel in screen space, the "screen-space shadow mask" of forward renderers.
// A software rasteriser such as llvmpipe shades in blocks of 4x4 pixels; a dense mesh's triangles
// cover a few pixels each and fill them poorly, so the shadow lookups, the costliest term of the
// mode, cost several times their share on the objects. Two passes before the lit one:
// - surfaces: the receivers (the opaque meshes the lit pass draws with the shadowed program; not a
//   planar ground, which reads its own visibility texture: ShadowMaps::groundVisibility),
//   with a position-only vertex shader (shadow_surface.vert, mesh.vert's invariant gl_Position)
//   and a tiny fragment shader (shadow_surface.frag) writing each visible pixel's world position
//   and geometric normal, and stencil 1;
// - mask: a full-screen triangle, stencil-tested, computing shadow.glsl's shadowVisibilities for
//   every light there (shadow_mask.frag): at divisor 1 two unorm16 per component of an RG32UI
//   texel, at divisor 2 light i in byte i of an R32UI texel (packUnorm4x8: one textureGather
//   brings 4 pixels' visibilities of every light);
// then the lit pass reads the mask (mesh.frag with SHADOW_MASK 1 or 2).
// - At the frame's resolution (divisor 1), the lit pass reads its pixel's texel. Its fragments
//   are the surface pass's (the same invariant gl_Position, depth test and culling), so the value
//   is the one the lit pass would have computed, to the mask's 16 bits.
// - At a coarser resolution (divisor 2: a mask pixel per 2 x 2 frame pixels, a quarter of the
//   lookups and of both passes' pixels), the lit pass upsamples it with its depth
//   (shadow.glsl's upsampledShadowMask): the bilinear weights of the 4 nearest mask pixels, each
//   kept only where that pixel's depth lies on the lit pixel's surface (its depth extrapolated
//   along the lit pixel's own depth gradient), else the one of nearest depth. Penumbrae are
//   interpolated; an edge between two surfaces stays sharp.
// Single-sample targets only: a multisampled frame shades a pixel's samples from different
// surfaces at its edges, and keeps reading the maps in the lit pass.
#include <epoxy/gl.h>

#include <map>
#include <utility>

#include "engine/gl/gpu_textures.h"
#include "engine/gl/shader_program.h"

namespace iblkit {

class ShadowMask {
 public:
  ShadowMask();  // needs a current OpenGL 4.5 context
  ~ShadowMask();
  ShadowMask(const ShadowMask&) = delete;
  ShadowMask& operator=(const ShadowMask&) = delete;

  // Starts the surface pass of a width x height frame with a mask of ceil(width / divisor) x
  // ceil(height / divisor) pixels (divisor 1 or 2): (re)allocates the targets when the size
  // changed, binds the surface framebuffer with viewport, depth test (GL_LESS) and stencil (write
  // 1 where a fragment passes) set, and clears depth (to 1, the far plane) and stencil (the
  // surfaces are read only where the stencil is 1). The caller then draws the receivers with
  // surfaceProgram() (its viewProjection set), culling as the lit pass does.
  void beginSurfaces(int width, int height, int divisor);
  // Mask pixels per frame pixel along x and y (1 at divisor 1): the lit pass's shadowMaskScale.
  float scaleX() const { return float(maskWidth_) / float(width_); }
  float scaleY() const { return float(maskHeight_) / float(height_); }
  const ShaderProgram& surfaceProgram() const { return surfaceProgram_; }

  // The mask pass's program for `lightCount` lights and the divisor of the last beginSurfaces
  // (compiled on first use); the caller sets its lights' and shadow maps' uniforms
  // (light_directions.glsl, shadow.glsl).
  const ShaderProgram& maskProgram(int lightCount);
  // Runs the mask pass with `program` (from maskProgram, uniforms set) over the stencilled pixels,
  // drawing a full-screen triangle with `emptyVertexArray` bound, then binds the mask to
  // kTextureUnitShadowMask and its depths to kTextureUnitShadowMaskDepth. Leaves the mask
  // framebuffer bound, stencil and depth test off.
  void computeMask(const ShaderProgram& program, GLuint emptyVertexArray);

 private:
  int width_ = 0, height_ = 0, divisor_ = 1, maskWidth_ = 0, maskHeight_ = 0;
  GlTexture surface_, depthStencil_, mask_;
  GLuint surfaceFramebuffer_ = 0, maskFramebuffer_ = 0;
  ShaderProgram surfaceProgram_{"shadow_surface.vert", "shadow_surface.frag"};
  std::map<std::pair<int, int>, ShaderProgram> maskPrograms_;  // by light count and MASK_BITS
};

}  // namespace iblkit
