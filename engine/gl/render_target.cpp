#include "engine/gl/render_target.h"

#include <string>
#include <utility>

#include "core/error.h"
#include "engine/gl/gpu_textures.h"

namespace iblkit {

void requireCompleteFramebuffer(GLuint framebuffer, std::string_view owner) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(std::string(owner) + ": framebuffer incomplete (status " + std::to_string(status) + ")");
}
namespace {

GLuint multisampledTexture(GLenum format, int width, int height, int samples) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &texture);
  glTextureStorage2DMultisample(texture, samples, format, width, height, GL_TRUE);
  return texture;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int msaaSamples)
    : width_(width), height_(height), samples_(msaaSamples > 1 ? msaaSamples : 1) {
  GLint maxSize = 0, maxSamples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize)
    throw Error("render target: size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside 1.." + std::to_string(maxSize));
  if (samples_ > maxSamples)
    throw Error("render target: " + std::to_string(samples_) + " samples requested, at most " +
                std::to_string(maxSamples) + " supported");

  resolvedColor_ = createTargetTexture(GL_RGBA32F, width, height);
  glCreateFramebuffers(1, &resolveFramebuffer_);
  glNamedFramebufferTexture(resolveFramebuffer_, GL_COLOR_ATTACHMENT0, resolvedColor_, 0);
  if (samples_ == 1) {
    depth_ = createTargetTexture(GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferTexture(resolveFramebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    drawFramebuffer_ = resolveFramebuffer_;
  } else {
    msaaColor_ = multisampledTexture(GL_RGBA32F, width, height, samples_);
    msaaDepth_ = multisampledTexture(GL_DEPTH_COMPONENT32F, width, height, samples_);
    glCreateFramebuffers(1, &drawFramebuffer_);
    glNamedFramebufferTexture(drawFramebuffer_, GL_COLOR_ATTACHMENT0, msaaColor_, 0);
    glNamedFramebufferTexture(drawFramebuffer_, GL_DEPTH_ATTACHMENT, msaaDepth_, 0);
    requireCompleteFramebuffer(drawFramebuffer_, "render target");
  }
  requireCompleteFramebuffer(resolveFramebuffer_, "render target");
}

RenderTarget::RenderTarget(RenderTarget&& other) noexcept { *this = std::move(other); }

RenderTarget& RenderTarget::operator=(RenderTarget&& other) noexcept {
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  std::swap(samples_, other.samples_);
  std::swap(drawFramebuffer_, other.drawFramebuffer_);
  std::swap(resolveFramebuffer_, other.resolveFramebuffer_);
  std::swap(msaaColor_, other.msaaColor_);
  std::swap(msaaDepth_, other.msaaDepth_);
  std::swap(resolvedColor_, other.resolvedColor_);
  std::swap(depth_, other.depth_);
  return *this;
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
  if (drawFramebuffer_ && drawFramebuffer_ != resolveFramebuffer_) glDeleteFramebuffers(1, &drawFramebuffer_);
  if (resolveFramebuffer_) glDeleteFramebuffers(1, &resolveFramebuffer_);
  for (GLuint texture : {msaaColor_, msaaDepth_, resolvedColor_, depth_})
    if (texture) glDeleteTextures(1, &texture);
}

void RenderTarget::resolve() {
  if (samples_ == 1) return;
  // A multisample resolve averages the samples of each pixel (OpenGL 4.5 section 18.3.1); on a
  // float buffer that is the linear box filter we want, alpha included (coverage).
  glBlitNamedFramebuffer(drawFramebuffer_, resolveFramebuffer_, 0, 0, width_, height_, 0, 0, width_, height_,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

Image RenderTarget::readColor() {
  resolve();
  Image image(width_, height_);
  std::vector<glm::vec4> rows(image.pixelCount());
  glGetTextureImage(resolvedColor_, 0, GL_RGBA, GL_FLOAT, GLsizei(rows.size() * sizeof(glm::vec4)),
                    rows.data());
  // GL's row 0 is the bottom of the image.
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      image.at(x, y) = rows[std::size_t(height_ - 1 - y) * std::size_t(width_) + std::size_t(x)];
  return image;
}

}  // namespace iblkit
