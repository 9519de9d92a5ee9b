#pragma once
// An offscreen framebuffer: RGBA32F colour and a 32-bit float depth buffer, optionally
// multisampled (resolved into a single-sample RGBA32F texture for reading and display).
#include <epoxy/gl.h>

#include <string_view>

#include "core/image.h"

namespace iblkit {

// Throws Error("<owner>: framebuffer incomplete (status N)") unless `framebuffer` is complete.
void requireCompleteFramebuffer(GLuint framebuffer, std::string_view owner);

class RenderTarget {
 public:
  // msaaSamples <= 1: no multisampling. Throws Error("render target: ...") for a size below 1 or
  // above GL_MAX_RENDERBUFFER_SIZE, more samples than GL_MAX_SAMPLES, or an incomplete framebuffer.
  RenderTarget(int width, int height, int msaaSamples);
  RenderTarget(RenderTarget&& other) noexcept;
  RenderTarget& operator=(RenderTarget&& other) noexcept;
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;
  ~RenderTarget();

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // The framebuffer to render into (the multisampled one when samples() > 1).
  GLuint framebuffer() const { return drawFramebuffer_; }
  // The single-sample colour texture; call resolve() first after multisampled rendering.
  GLuint colorTexture() const { return resolvedColor_; }
  // Resolves the multisampled colour into colorTexture() (a box filter over the samples, in
  // linear float). Nothing to do without multisampling.
  void resolve();
  // Resolves and reads the colour back as linear RGBA float, row 0 at the top (Image's
  // convention; GL's row 0 is the bottom, so rows are flipped).
  Image readColor();

 private:
  void release();
  int width_ = 0, height_ = 0, samples_ = 1;
  GLuint drawFramebuffer_ = 0, resolveFramebuffer_ = 0;
  GLuint msaaColor_ = 0, msaaDepth_ = 0, resolvedColor_ = 0, depth_ = 0;
};

}  // namespace iblkit
