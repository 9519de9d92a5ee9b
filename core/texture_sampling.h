#pragma once
// Sampling glTF textures on the CPU, the way OpenGL samples them (OpenGL 4.5 core, section 8.14
// "Texture Minification" and 8.15 "Texture Magnification"), so that the reference and the baker
// read the same values the raster does:
// - Mip chains are built once per (image, colour space) by buildMipChain; the engine uploads these
//   very levels, so both sides filter the same texels.
// - sRGB texels are decoded (IEC 61966-2-1) before filtering, as GL does for SRGB8_ALPHA8.
// - Wrap modes REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT per axis; texel centres at (i + 0.5) / size.
// - The level of detail is lambda = log2(rho), rho the footprint in texels; magnification
//   (lambda <= 0) uses magFilter, minification minFilter and, with mipmaps, the mip filter between
//   floor(lambda) and floor(lambda) + 1 (GL's LINEAR_MIPMAP_LINEAR is trilinear).
// The footprint rule of the reference (ray cones) is in docs/material-model.md "Texture filtering".

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "core/material.h"
#include "core/texture.h"

namespace iblkit {

// IEC 61966-2-1 sRGB decoding of an 8-bit value: 188 -> 0.5029.
float srgbToLinear(std::uint8_t value);
// The decoding of every 8-bit value (index 0..255), for per-texel lookups.
const float* srgbDecodeTable();

// One image in one colour space, level 0 (the image) down to 1 x 1: level i is
// max(1, floor(size / 2^i)) on each axis (GL's rule for glGenerateMipmap), each texel the box
// average of the 2 x 2 (or 2 x 1, or 3 x n for odd sizes) texels under it, averaged in linear
// space for sRGB images (decode, average, encode) and rounded to 8 bits.
struct MipLevel {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, in the chain's colour space
  // The same texels decoded (linear RGBA floats, width * height * 4: the chain's sRGB or linear
  // decoding of rgba), or empty. decodeSmallLevels fills it; lookups then load one texel's four
  // channels at once instead of decoding four bytes through the tables, with the same values.
  std::vector<float> decoded;
};
struct MipChain {
  ColorSpace colorSpace = ColorSpace::Linear;
  std::vector<MipLevel> levels;
  // Every texel of every level has alpha 255 (buildMipChain sets it), so that every filtered
  // alpha is exactly 1: the weights of a lookup sum to exactly 1 in float (1 - f + f rounds to 1
  // for every float f in [0, 1]). A ray's alpha test can then be decided without a lookup.
  bool alphaAllOne = false;
  // The first level with decoded texels (decodeSmallLevels; levels only shrink, so every later
  // level has them too); levels.size() or more when none has.
  int decodedFrom = std::numeric_limits<int>::max();
  int width() const { return levels.empty() ? 0 : levels[0].width; }
  int height() const { return levels.empty() ? 0 : levels[0].height; }
};
MipChain buildMipChain(const TextureImage& image, ColorSpace colorSpace);

// Levels of at most this many texels get decoded texels (MipLevel::decoded, 16 bytes a texel:
// at most 1 MiB a level, 4/3 MiB the decoded tail of a chain). Most lookups read such levels: a
// level of detail picks about one texel per footprint, so a level above 256 x 256 is read only
// where a surface spans more than 256 footprints across (the tracer's camera cone is half a pixel).
inline constexpr int kDecodedLevelTexels = 256 * 256;
// Fills MipLevel::decoded for every level of `chain` with at most kDecodedLevelTexels texels.
void decodeSmallLevels(MipChain& chain);

// The level of detail lambda for an isotropic footprint `footprintUv` wide in uv units (0: the
// finest level): log2(footprintUv * sqrt(width * height)) of level 0 (Akenine-Möller et al. 2019,
// "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20).
float textureLod(const MipChain& chain, float footprintUv);

// The filtered, decoded (linear RGBA) value of `chain` at `uv` (after KHR_texture_transform) with
// level of detail `lod`, sampled as `sampler` says.
glm::vec4 sampleMipChain(const MipChain& chain, const TextureSampler& sampler, glm::vec2 uv, float lod);

// The wrapped texel index for integer coordinate i on an axis of `size` texels.
int wrapTexel(int i, int size, TextureWrap wrap);

// Every texture of a scene, ready to sample: one MipChain per texture in each colour space the
// scene's materials read it in (a texture used by two slots of different colour spaces gets two).
class SceneTextures {
 public:
  SceneTextures() = default;
  // Builds the chains for textures[*] over images[*] as materials' slots use them.
  SceneTextures(const std::vector<Texture>& textures, const std::vector<TextureImage>& images,
                const std::vector<Material>& materials);

  bool empty() const { return textures_.empty(); }
  // The chain of texture `texture` in `colorSpace`; nullptr if no slot reads it that way.
  const MipChain* chain(int texture, ColorSpace colorSpace) const;
  const TextureSampler& sampler(int texture) const;

  // The slot's filtered value: ref's transform applied to `uv` (the texCoord set ref names),
  // the footprint converted to a lod for this texture. ref must be present().
  glm::vec4 sample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv, float footprintUv) const;

  // The same lookup for a caller that reads several slots of one uv set: `log2FootprintUv` is
  // log2Footprint(footprintUv), taken once per set rather than once per slot, since
  // lambda = log2(footprint) + log2(sqrt(width * height)) + log2(sqrt|scale.x scale.y|) and the
  // last two are per texture (precomputed here) and per ref. Returns false, leaving `value`, when
  // ref names no chain in `colorSpace`.
  static float log2Footprint(float footprintUv);
  bool trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv, float log2FootprintUv,
                 glm::vec4& value) const;

  // Channel masks for trySample's `channels` (bit k: channel k, R G B A): a slot that uses only
  // some channels (glTF 2.0 section 3.9: metallic-roughness G and B, occlusion R, normal and
  // emissive RGB) skips the other texels' loads and decodes in the common REPEAT power-of-two
  // LINEAR path. The channels read are the same values as with kRgba; the others are
  // unspecified (0 on the fast path, the texel's elsewhere).
  static constexpr unsigned kRed = 0x1, kGreenBlue = 0x6, kRgb = 0x7, kAlpha = 0x8, kRgba = 0xF;
  bool trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv, float log2FootprintUv,
                 glm::vec4& value, unsigned channels) const;

  // One slot's lookup in sampleSlots: `value` and `found` are trySample's value and result.
  struct SlotLookup {
    const TextureRef* ref = nullptr;  // present()
    ColorSpace colorSpace = ColorSpace::Linear;
    unsigned channels = kRgba;
    glm::vec4 value{1.0f};
    bool found = false;
  };
  // The lookups of several slots at one point (evaluateSurfaceMaterial's), each the value of
  // trySample(*ref, colorSpace, texcoords[set], log2Footprint(footprintUv[set]), value, channels).
  // Slots that read through the same uv set, transform and sampler from textures of the same size
  // (the usual glTF material: one uv layout, one sampler) share the transformed uv, the level of
  // detail, the levels and the texel addresses and weights, worked out once; each slot then only
  // loads and blends its own texels.
  void sampleSlots(SlotLookup* lookups, int count, const glm::vec2 texcoords[2],
                   const float footprintUv[2]) const;

  // sampleSlots' lookups worked out once, for a caller that reads the same slots at many points
  // (the tracer: one set per material): each lookup's chain, and which lookups share a plan (the
  // same uv set, transform and layout), found when the set is made rather than at every point;
  // the lod's per-texture and per-transform terms precomputed. sample() gives sampleSlots' values
  // bit for bit (sampleSlots makes a set per call). It points into the SceneTextures it was made
  // from, which must outlive it (and not be copied over or moved from).
  class SlotSet {
   public:
    static constexpr int kMaxLookups = 8;
    SlotSet() = default;
    // lookups[0, count) (their ref, colorSpace and channels; count <= kMaxLookups). The refs are
    // copied: they need not outlive the set.
    SlotSet(const SceneTextures& textures, const SlotLookup* lookups, int count);
    // Whether lookup l names a chain (sampleSlots' `found`).
    bool found(int l) const { return (found_ >> l) & 1u; }
    // sampleSlots' value of each found lookup l whose bit (1 << l) is set in `active`, written to
    // values[l]; other values are left as they are.
    void sample(const glm::vec2 texcoords[2], const float footprintUv[2], glm::vec4* values,
                unsigned active = ~0u) const;

   private:
    // Lookups sharing one plan: the uv set, transform, sampler and level sizes.
    struct Group {
      int set = 0;
      TextureTransform transform;
      TextureSampler sampler;
      const MipChain* sizes = nullptr;  // the first lookup's chain (the group's level sizes)
      float log2Size = 0.0f;            // log2(sqrt(width * height)) of level 0
      bool scaled = false;              // the transform scales: lod += log2Scale (slotLod)
      float log2Scale = 0.0f;
      int layout = -1;       // SceneTextures::Entry::layout
      unsigned lookups = 0;  // bits of the group's lookups
      int first = 0, count = 0;  // its slots in slots_
    };
    struct Slot {
      const MipChain* chain = nullptr;
      unsigned channels = kRgba;
      int lookup = 0;
    };
    Group groups_[kMaxLookups];
    Slot slots_[kMaxLookups];
    int groupCount_ = 0;
    unsigned found_ = 0;
  };

 private:
  struct Entry {
    TextureSampler sampler;
    int linear = -1, srgb = -1;  // indices into chains_
    // Textures of one layout (the same sampler, and chains of the same level sizes: from images
    // of one size) share a number, the first such texture's index; sampleSlots shares plans
    // within it.
    int layout = -1;
  };
  std::vector<Entry> textures_;
  std::vector<MipChain> chains_;
  std::vector<float> chainLog2Size_;  // per chain: log2(sqrt(width * height)) of level 0
  // The chain ref reads in colorSpace, -1 if none; the lod of ref's lookup in chain `chain`.
  int chainIndex(const TextureRef& ref, ColorSpace colorSpace) const;
  float slotLod(const TextureRef& ref, int chain, float log2FootprintUv) const;
};

}  // namespace iblkit
