#include "engine/gl/gpu_textures.h"

#include <algorithm>
#include <bit>
#include <iostream>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/image.h"

namespace iblkit {

GlTexture::GlTexture(GlTexture&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

GlTexture& GlTexture::operator=(GlTexture&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

GlTexture::~GlTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

GLuint createTargetTexture(GLenum format, int width, int height) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

namespace {

// The context's `limit`: GL_MAX_TEXTURE_SIZE or GL_MAX_CUBE_MAP_TEXTURE_SIZE.
GLint largestTexture(GLenum limit) {
  GLint largest = 0;
  glGetIntegerv(limit, &largest);
  return largest;
}

// The levels of a whole mip chain of a width x height texture, down to 1 x 1.
GLsizei fullMipLevels(int width, int height) { return GLsizei(std::bit_width(unsigned(std::max(width, height)))); }

}  // namespace

void requireTextureFits(int width, int height, GLenum limit, const char* what) {
  const GLint largest = largestTexture(limit);
  if (width <= largest && height <= largest) return;
  throw Error(std::string(what) + " is " + std::to_string(width) + " x " + std::to_string(height) +
              " texels, larger than this OpenGL's largest texture (" + std::to_string(largest) + " on a side)");
}

namespace {

// `image` as RGBA32F, row 0 first, bilinear; with `mipmaps`, the whole chain of box-filtered levels
// (glGenerateTextureMipmap), trilinear between them. Not anisotropic: llvmpipe's anisotropic
// lookups of this float texture left bright specks along a mirror sphere's rings (the
// frame's relMSE 9.5 against 0.3 without them).
GlTexture upload2D(const Image& image, GLenum wrapS, GLenum wrapT, const char* what, bool mipmaps = false) {
  if (image.empty()) throw Error("texture upload: empty image");
  requireTextureFits(image.width(), image.height(), GL_MAX_TEXTURE_SIZE, what);
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  const GLsizei levels = mipmaps ? fullMipLevels(image.width(), image.height()) : 1;
  glTextureStorage2D(id, levels, GL_RGBA32F, image.width(), image.height());
  glTextureSubImage2D(id, 0, 0, 0, image.width(), image.height(), GL_RGBA, GL_FLOAT, image.pixels().data());
  if (mipmaps) glGenerateTextureMipmap(id);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrapS));
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrapT));
  return GlTexture(id);
}

}  // namespace

bool latLongFits(int width, int height) {
  const GLint largest = largestTexture(GL_MAX_TEXTURE_SIZE);
  if (width > largest || height > largest) return false;
  // The proxy target answers without allocating (OpenGL 4.5 section 8.22): its level 0 has width 0
  // when the implementation cannot hold the texture.
  glTexStorage2D(GL_PROXY_TEXTURE_2D, fullMipLevels(width, height), GL_RGBA32F, width, height);
  GLint proxyWidth = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &proxyWidth);
  return proxyWidth == width;
}

GlTexture uploadLatLong(const Image& latLong) {
  if (latLong.empty()) throw Error("texture upload: empty image");
  if (latLongFits(latLong.width(), latLong.height()))
    return upload2D(latLong, GL_REPEAT, GL_CLAMP_TO_EDGE, "the environment map", true);
  Image halved = downsample2x(latLong);
  while (!latLongFits(halved.width(), halved.height()) && halved.width() > 1) halved = downsample2x(halved);
  std::cerr << "the environment map (" << latLong.width() << " x " << latLong.height() << ") is drawn at "
            << halved.width() << " x " << halved.height()
            << ": this OpenGL cannot hold it with its mip levels as RGBA32F\n";
  return upload2D(halved, GL_REPEAT, GL_CLAMP_TO_EDGE, "the environment map", true);
}

GlTexture uploadTable(const Image& table) { return upload2D(table, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, "a table"); }

GlTexture uploadCubeLevels(const CubeMapLevels& levels) {
  if (levels.empty() || levels.front().size < 1) throw Error("texture upload: empty cube map chain");
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
  const int size = levels.front().size;
  requireTextureFits(size, size, GL_MAX_CUBE_MAP_TEXTURE_SIZE, "a cube map's face");
  glTextureStorage2D(id, GLsizei(levels.size()), GL_RGBA32F, size, size);
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const CubeMap& cube = levels[level];
    for (int face = 0; face < 6; ++face)
      // For cube maps, glTextureSubImage3D's z offset selects the face (OpenGL 4.5 section 8.6).
      glTextureSubImage3D(id, GLint(level), 0, 0, face, cube.size, cube.size, 1, GL_RGBA, GL_FLOAT,
                          cube.faces[std::size_t(face)].pixels().data());
  }
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAX_LEVEL, GLint(levels.size()) - 1);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(id, wrap, GL_CLAMP_TO_EDGE);
  return GlTexture(id);
}

}  // namespace iblkit
