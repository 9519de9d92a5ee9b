#include "engine/gl/shadow_mask.h"

#include <string>

#include "core/error.h"
#include "engine/gl/light_constants.h"
#include "engine/gl/render_target.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {

// One visibility per component of the mask's RGBA texel (shadow.glsl's shadowVisibilities).
static_assert(kMaxEngineLights <= 4, "the shadow mask holds at most 4 lights");

ShadowMask::ShadowMask() {
  glCreateFramebuffers(1, &surfaceFramebuffer_);
  glCreateFramebuffers(1, &maskFramebuffer_);
}

ShadowMask::~ShadowMask() {
  if (surfaceFramebuffer_) glDeleteFramebuffers(1, &surfaceFramebuffer_);
  if (maskFramebuffer_) glDeleteFramebuffers(1, &maskFramebuffer_);
}

void ShadowMask::beginSurfaces(int width, int height, int divisor) {
  if (divisor != 1 && divisor != 2)
    throw Error("shadow mask: divisor " + std::to_string(divisor) + " (1 or 2 expected)");
  const int maskWidth = (width + divisor - 1) / divisor, maskHeight = (height + divisor - 1) / divisor;
  if (width != width_ || height != height_ || divisor != divisor_ || maskWidth != maskWidth_ ||
      maskHeight != maskHeight_) {
    surface_ = GlTexture(createTargetTexture(GL_RGBA32UI, maskWidth, maskHeight));
    depthStencil_ = GlTexture(createTargetTexture(GL_DEPTH32F_STENCIL8, maskWidth, maskHeight));
    // Sampled as depth by the lit pass (the default mode, set for clarity).
    glTextureParameteri(depthStencil_.id(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    // Two unorm16 per component at the frame's resolution (the lit pass's own visibilities to 16
    // bits); four unorm8 in one component at a coarser one, which one textureGather reads for 4
    // pixels (its upsampling's error is far above 8 bits': shadow_mask.frag's MASK_BITS).
    mask_ = GlTexture(createTargetTexture(divisor == 1 ? GL_RG32UI : GL_R32UI, maskWidth, maskHeight));
    glNamedFramebufferTexture(surfaceFramebuffer_, GL_COLOR_ATTACHMENT0, surface_.id(), 0);
    glNamedFramebufferTexture(surfaceFramebuffer_, GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_.id(), 0);
    glNamedFramebufferTexture(maskFramebuffer_, GL_COLOR_ATTACHMENT0, mask_.id(), 0);
    glNamedFramebufferTexture(maskFramebuffer_, GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_.id(), 0);
    requireCompleteFramebuffer(surfaceFramebuffer_, "shadow mask");
    requireCompleteFramebuffer(maskFramebuffer_, "shadow mask");
    width_ = width;
    height_ = height;
    maskWidth_ = maskWidth;
    maskHeight_ = maskHeight;
  }
  divisor_ = divisor;
  glBindFramebuffer(GL_FRAMEBUFFER, surfaceFramebuffer_);
  glViewport(0, 0, maskWidth_, maskHeight_);
  glDisable(GL_SAMPLE_SHADING);
  glClearNamedFramebufferfi(surfaceFramebuffer_, GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilMask(0xff);
  surfaceProgram_.use();
}

const ShaderProgram& ShadowMask::maskProgram(int lightCount) {
  const int bits = divisor_ == 1 ? 16 : 8;
  const std::pair<int, int> key(lightCount, bits);
  auto found = maskPrograms_.find(key);
  if (found == maskPrograms_.end())
    found = maskPrograms_
                .emplace(key, ShaderProgram("fullscreen.vert", "shadow_mask.frag",
                                            "#define LIGHT_COUNT " + std::to_string(lightCount) +
                                                "\n#define MASK_BITS " + std::to_string(bits)))
                .first;
  return found->second;
}

void ShadowMask::computeMask(const ShaderProgram& program, GLuint emptyVertexArray) {
  glBindFramebuffer(GL_FRAMEBUFFER, maskFramebuffer_);
  glViewport(0, 0, maskWidth_, maskHeight_);
  // A coarser mask is read around a pixel's own texel too, where a pixel without a receiver may
  // be the nearest (upsampledShadowMask's fallback): lit, not last frame's value.
  if (divisor_ > 1) {
    const GLuint lit[4] = {0xffffffffu, 0xffffffffu, 0u, 0u};
    glClearNamedFramebufferuiv(maskFramebuffer_, GL_COLOR, 0, lit);
  }
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glBindTextureUnit(kTextureUnitShadowSurface, surface_.id());
  program.use();
  glBindVertexArray(emptyVertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_STENCIL_TEST);
  glBindTextureUnit(kTextureUnitShadowSurface, 0);
  glBindTextureUnit(kTextureUnitShadowMask, mask_.id());
  glBindTextureUnit(kTextureUnitShadowMaskDepth, depthStencil_.id());
}

}  // namespace iblkit
