#pragma once
// Uploads of the engine's textures (OpenGL 4.5 direct state access), owned by GlTexture.
#include <epoxy/gl.h>

#include "core/cube_map.h"
#include "core/image.h"

namespace iblkit {

// An owned texture name (deleted with the object; needs the context current).
class GlTexture {
 public:
  GlTexture() = default;
  explicit GlTexture(GLuint id) : id_(id) {}
  GlTexture(GlTexture&& other) noexcept;
  GlTexture& operator=(GlTexture&& other) noexcept;
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;
  ~GlTexture();
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

// An uninitialised width x height 2D texture of `format`, one level, nearest filtering, clamped to
// the edge: a render target's attachment. The caller owns the name (GlTexture, or its own).
GLuint createTargetTexture(GLenum format, int width, int height);

// Throws Error("<what> is W x H texels, larger than this OpenGL's largest texture (N on a side)")
// when width or height exceeds the context's `limit` (GL_MAX_TEXTURE_SIZE, or
// GL_MAX_CUBE_MAP_TEXTURE_SIZE for a cube's faces): the upload would fail with GL_INVALID_VALUE and
// leave the texture empty, drawing black where the map or texture belongs. A 32768-wide photograph
// exceeds llvmpipe's 16384; some GPUs stop at 8192 or 16384.
void requireTextureFits(int width, int height, GLenum limit, const char* what);

// A lat-long map as RGBA32F with image row 0 first (v = 0 at t = 0), repeating in s and clamped
// in t, with its chain of box-filtered mip levels. Read at lod 0 it is the core's
// sampleLatLongBilinear; sampleLatLongFootprint (latlong_footprint.glsl) reads it trilinearly
// through a pixel's footprint. A map this OpenGL cannot hold so (latLongFits) is drawn from its
// largest box-filtered half that it can (downsample2x, the chain's next level), with a note on
// stderr: wider than the largest texture, or, on llvmpipe, past its 1 GiB a texture (a 16384 x
// 8192 map's chain is 2.7 GiB; 8192 x 4096, 683 MiB, fits).
GlTexture uploadLatLong(const Image& latLong);

// Whether this OpenGL can hold a width x height RGBA32F texture with its whole mip chain: both
// sides within GL_MAX_TEXTURE_SIZE, and the proxy texture of that storage accepted.
bool latLongFits(int width, int height);

// A cube mip chain (cube_map.h, OpenGL's face layout; level sizes halving down to 1) as an RGBA32F
// cube map, trilinear (GL_LINEAR_MIPMAP_LINEAR) between levels. Seamless filtering across faces is
// a context-wide switch (GL_TEXTURE_CUBE_MAP_SEAMLESS) the renderer turns on.
GlTexture uploadCubeLevels(const CubeMapLevels& levels);

// A 2D table (the DFG LUT) as RGBA32F, row 0 first, bilinear, clamped.
GlTexture uploadTable(const Image& table);

}  // namespace iblkit
