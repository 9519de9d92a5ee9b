#pragma once
// Textures as glTF 2.0 defines them (section 3.8 and 5.26-5.29): a texture is an image plus a
// sampler; a material slot refers to a texture with a texCoord set, an optional
// KHR_texture_transform and its colour space. Images are kept decoded as 8-bit RGBA exactly as
// stored (sRGB values stay sRGB-encoded: the slot decides how to read them, as OpenGL's SRGB8_ALPHA8
// does), and with the bytes of the file they came from, so the baker can copy them unchanged.
// Sampling (wrap, filters, mip chains, the level of detail) is in texture_sampling.h; the material
// evaluation that uses it is in surface_material.h.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace iblkit {

// glTF sampler wrap modes (the numbers are the GL enums glTF uses).
enum class TextureWrap { Repeat = 10497, ClampToEdge = 33071, MirroredRepeat = 33648 };
enum class TextureFilter { Nearest, Linear };

// A glTF sampler. glTF leaves absent filters to the implementation; iblkit's choice is LINEAR
// magnification and LINEAR_MIPMAP_LINEAR minification (trilinear), which is also what a sampler
// with filters absent gets. minFilter NEAREST or LINEAR (no MIPMAP) sets mipmaps = false.
struct TextureSampler {
  TextureWrap wrapS = TextureWrap::Repeat;
  TextureWrap wrapT = TextureWrap::Repeat;
  TextureFilter magFilter = TextureFilter::Linear;
  TextureFilter minFilter = TextureFilter::Linear;  // within a mip level
  bool mipmaps = true;                              // minification uses the mip chain
  TextureFilter mipFilter = TextureFilter::Linear;  // between mip levels (minFilter *_MIPMAP_LINEAR)
};

// How a slot reads an image's RGB (alpha is always linear): IEC 61966-2-1 sRGB for base colour
// and emissive, linear for metallic-roughness, normal and occlusion.
enum class ColorSpace { Linear, Srgb };

// A decoded glTF image.
struct TextureImage {
  std::string name;      // glTF image name (may be empty)
  std::string mimeType;  // "image/png", "image/jpeg" or "image/webp"
  // Where it came from, for messages and for iblkit-info: the image file, or the glTF file for an
  // image embedded in a buffer view or a data: URI.
  std::filesystem::path file;
  std::string uri;  // the glTF image's uri as written (empty for a buffer view; a data: URI only up
                    // to its comma, "data:image/png;base64,")
  int width = 0, height = 0;
  int channels = 4;                // channels the encoded file has (1 grey .. 4 RGBA), for info
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row 0 at the top (glTF uv (0, 0))
  std::vector<std::uint8_t> encoded;  // the file's bytes as stored (PNG, JPEG or WebP)
};

// A glTF texture: an image and a sampler.
struct Texture {
  std::string name;
  int image = -1;  // index into Scene::images
  TextureSampler sampler;
};

// KHR_texture_transform: uv' = translation(offset) * rotation(rotation) * scale(scale) * uv, with
// the extension's rotation (radians, counter-clockwise in uv space as the extension defines it).
struct TextureTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;
  glm::vec2 scale{1.0f};
  bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
  // The 3x3 matrix of the extension (column-major, acting on (u, v, 1)).
  glm::mat3 matrix() const;
  glm::vec2 apply(glm::vec2 uv) const;
};

// The largest |offset|, |rotation| (radians), |scale| of a texture transform and |normalTexture
// scale| the loaders accept: far beyond any tiling or bump strength, and small enough that uv *
// scale and the ray cones' footprints stay finite in float (1e300 in a file would become Inf).
inline constexpr double kMaxTextureTransformValue = 1e6;

// A material slot's texture reference (glTF textureInfo). texture < 0: the slot has no texture.
struct TextureRef {
  int texture = -1;   // index into Scene::textures
  int texCoord = 0;   // TEXCOORD_n set (0 or 1); KHR_texture_transform's texCoord already applied
  TextureTransform transform;
  bool present() const { return texture >= 0; }
};

// The material's texture slots, as bits, for switching slots off (the viewer panel, the tracer's
// --no-textures, the benchmarks).
enum TextureSlot : unsigned {
  kSlotBaseColor = 1u << 0,
  kSlotMetallicRoughness = 1u << 1,
  kSlotNormal = 1u << 2,
  kSlotOcclusion = 1u << 3,
  kSlotEmissive = 1u << 4,
  kAllTextureSlots = (1u << 5) - 1,
};

}  // namespace iblkit
