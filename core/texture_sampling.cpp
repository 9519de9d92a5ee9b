#include "core/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace iblkit {

namespace {

// IEC 61966-2-1:1999, section 5.2 (the inverse of its encoding, 5.3).
double srgbDecode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

struct DecodeTables {
  std::array<float, 256> srgb{};
  std::array<float, 256> linear{};
  // The encoded 8-bit value is the one whose decoding is nearest: encode through the midpoints
  // between neighbouring decodings (monotone), so decode(encode(x)) is as close to x as 8 bits allow.
  std::array<float, 255> srgbMidpoints{};
  DecodeTables() {
    for (int i = 0; i < 256; ++i) {
      srgb[i] = static_cast<float>(srgbDecode(i / 255.0));
      linear[i] = static_cast<float>(i / 255.0);
    }
    for (int i = 0; i < 255; ++i) srgbMidpoints[i] = 0.5f * (srgb[i] + srgb[i + 1]);
  }
};

const DecodeTables& tables() {
  static const DecodeTables instance;
  return instance;
}

std::uint8_t encodeLinear(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

std::uint8_t encodeSrgb(float value) {
  const auto& midpoints = tables().srgbMidpoints;
  return static_cast<std::uint8_t>(std::upper_bound(midpoints.begin(), midpoints.end(), value) -
                                   midpoints.begin());
}

// The box filter of one axis from `size` texels to `reduced`: output texel i covers the source
// interval [i size / reduced, (i + 1) size / reduced), each source texel weighted by its overlap
// (2 texels for even sizes; for odd sizes 3, the outer two partly), so that every source texel
// counts equally and the level keeps the image's mean.
struct Tap {
  int index;
  float weight;
};
std::vector<std::vector<Tap>> boxTaps(int size, int reduced) {
  std::vector<std::vector<Tap>> taps(reduced);
  const double step = static_cast<double>(size) / reduced;
  for (int i = 0; i < reduced; ++i) {
    const double begin = i * step, end = (i + 1) * step;
    for (int s = static_cast<int>(std::floor(begin)); s < size && s < end; ++s) {
      const double overlap = std::min<double>(s + 1, end) - std::max<double>(s, begin);
      if (overlap > 1e-9) taps[i].push_back({s, static_cast<float>(overlap / step)});
    }
  }
  return taps;
}

// Level `level` of the chain, down-sampled by the box filter in linear values.
MipLevel reduce(const MipLevel& source, ColorSpace colorSpace) {
  MipLevel out;
  out.width = std::max(1, source.width / 2);
  out.height = std::max(1, source.height / 2);
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  const auto tapsX = boxTaps(source.width, out.width);
  const auto tapsY = boxTaps(source.height, out.height);
  const float* rgbTable = colorSpace == ColorSpace::Srgb ? tables().srgb.data() : tables().linear.data();
  const float* alphaTable = tables().linear.data();
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (const Tap& ty : tapsY[y])
        for (const Tap& tx : tapsX[x]) {
          const std::uint8_t* texel =
              &source.rgba[(static_cast<std::size_t>(ty.index) * source.width + tx.index) * 4];
          const float weight = ty.weight * tx.weight;
          for (int c = 0; c < 3; ++c) sum[c] += weight * rgbTable[texel[c]];
          sum[3] += weight * alphaTable[texel[3]];
        }
      std::uint8_t* texel = &out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4];
      for (int c = 0; c < 3; ++c)
        texel[c] = colorSpace == ColorSpace::Srgb ? encodeSrgb(sum[c]) : encodeLinear(sum[c]);
      texel[3] = encodeLinear(sum[3]);
    }
  return out;
}

// Texel coordinate before wrapping: floor(x), with x held in a range where the int conversion
// is defined (a texture coordinate beyond 2^24 texels has no fractional precision left anyway).
int floorToInt(float x) {
  if (!(x == x)) return 0;  // NaN
  return static_cast<int>(std::floor(std::clamp(x, -16777216.0f, 16777216.0f)));
}

// rgbTable decodes R, G and B; alpha is always linear (the table's linear half). A level with
// decoded texels holds these very values.
glm::vec4 fetch(const MipLevel& level, const float* rgbTable, const float* alphaTable, int x, int y) {
  const std::size_t index = (static_cast<std::size_t>(y) * level.width + x) * 4;
  if (!level.decoded.empty()) {
    const float* texel = &level.decoded[index];
    return glm::vec4(texel[0], texel[1], texel[2], texel[3]);
  }
  const std::uint8_t* texel = &level.rgba[index];
  return glm::vec4(rgbTable[texel[0]], rgbTable[texel[1]], rgbTable[texel[2]], alphaTable[texel[3]]);
}

// Four floats, one per channel, blended lane by lane: one SSE register where the target has SSE2
// (every x86-64 target), four scalars elsewhere. Each lane does the IEEE operations the scalar
// code does (no fused multiply-add: the x86-64 baseline has none), so the results are the same.
struct Lanes4 {
#if defined(__SSE2__)
  __m128 v;
  static Lanes4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  static Lanes4 set(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
  static Lanes4 splat(float x) { return {_mm_set1_ps(x)}; }
  friend Lanes4 operator*(Lanes4 a, Lanes4 b) { return {_mm_mul_ps(a.v, b.v)}; }
  friend Lanes4 operator+(Lanes4 a, Lanes4 b) { return {_mm_add_ps(a.v, b.v)}; }
  // The lanes whose bit is set in `channels` (bit k: lane k), the others 0.
  template <unsigned kChannels>
  Lanes4 masked() const {
    if constexpr (kChannels == 0xF) return *this;
    const __m128 keep = _mm_castsi128_ps(_mm_setr_epi32(kChannels & 1u ? -1 : 0, kChannels & 2u ? -1 : 0,
                                                        kChannels & 4u ? -1 : 0, kChannels & 8u ? -1 : 0));
    return {_mm_and_ps(v, keep)};
  }
  void store(glm::vec4& out) const { _mm_storeu_ps(&out.x, v); }
#else
  float v[4];
  static Lanes4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static Lanes4 set(float x, float y, float z, float w) { return {{x, y, z, w}}; }
  static Lanes4 splat(float x) { return {{x, x, x, x}}; }
  friend Lanes4 operator*(Lanes4 a, Lanes4 b) { return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}}; }
  friend Lanes4 operator+(Lanes4 a, Lanes4 b) { return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}}; }
  template <unsigned kChannels>
  Lanes4 masked() const {
    Lanes4 out = *this;
    for (int k = 0; k < 4; ++k)
      if (!((kChannels >> k) & 1u)) out.v[k] = 0.0f;
    return out;
  }
  void store(glm::vec4& out) const { out = glm::vec4(v[0], v[1], v[2], v[3]); }
#endif
};

// The wrapped neighbours i0 = wrap(i), i1 = wrap(i + 1) of a LINEAR lookup; REPEAT (the common
// case) without a second division.
void wrapPair(int i, int size, TextureWrap wrap, int& i0, int& i1) {
  i0 = wrapTexel(i, size, wrap);
  if (wrap == TextureWrap::Repeat)
    i1 = i0 + 1 == size ? 0 : i0 + 1;
  else
    i1 = wrapTexel(i + 1, size, wrap);
}

// GL 4.5 section 8.14.2: NEAREST takes the texel containing (u, v); LINEAR the 2 x 2 texels
// around it, at i0 = wrap(floor(u' - 1/2)), i1 = wrap(i0 + 1), weighted by frac(u' - 1/2).
glm::vec4 sampleLevel(const MipLevel& level, const float* rgbTable, const TextureSampler& sampler,
                      glm::vec2 uv, TextureFilter filter) {
  const float* alphaTable = tables().linear.data();
  const float x = uv.x * level.width, y = uv.y * level.height;
  if (filter == TextureFilter::Nearest)
    return fetch(level, rgbTable, alphaTable, wrapTexel(floorToInt(x), level.width, sampler.wrapS),
                 wrapTexel(floorToInt(y), level.height, sampler.wrapT));
  const float xs = std::isfinite(x) ? x - 0.5f : 0.0f, ys = std::isfinite(y) ? y - 0.5f : 0.0f;
  const float xFloor = std::floor(xs), yFloor = std::floor(ys);
  const float fx = xs - xFloor, fy = ys - yFloor;
  int i0, i1, j0, j1;
  wrapPair(floorToInt(xFloor), level.width, sampler.wrapS, i0, i1);
  wrapPair(floorToInt(yFloor), level.height, sampler.wrapT, j0, j1);
  const glm::vec4 top =
      glm::mix(fetch(level, rgbTable, alphaTable, i0, j0), fetch(level, rgbTable, alphaTable, i1, j0), fx);
  const glm::vec4 bottom =
      glm::mix(fetch(level, rgbTable, alphaTable, i0, j1), fetch(level, rgbTable, alphaTable, i1, j1), fx);
  return glm::mix(top, bottom, fy);
}

// sampleLevel's LINEAR lookup for the common case, inlined into sampleMipChain's lookups (a call per
// level returned the vec4 through the stack, and the perf profile showed the stall): both wraps
// REPEAT on power-of-two sizes (a mask, no switch) and the coordinate well inside int range.
// The same texels, weights and arithmetic order as sampleLevel, so the same result; false for
// anything else, which then takes sampleLevel.
// kChannels (SceneTextures::kRgba ...): the channels computed, the others set to 0 without
// loading their texels. A level with decoded texels loads each texel's channels at once (its
// values are the tables' decodings) and blends the four channels in one Lanes4.
template <unsigned kChannels = 0xF>
[[gnu::always_inline]] inline bool bilinearRepeatPow2(const MipLevel& level, const float* rgbTable,
                                                      const float* alphaTable, glm::vec2 uv, Lanes4& out) {
  const int w = level.width, h = level.height;
  if (((w & (w - 1)) | (h & (h - 1))) != 0) return false;
  const float xs = uv.x * w - 0.5f, ys = uv.y * h - 0.5f;
  if (!(std::abs(xs) < 16777216.0f && std::abs(ys) < 16777216.0f)) return false;  // NaN, inf, huge
  // floor without libm's call (std::floor is not inlined without SSE4.1): truncate, then step
  // down for negative non-integers; exact for |x| < 2^24.
  int i = static_cast<int>(xs), j = static_cast<int>(ys);
  i -= static_cast<float>(i) > xs;
  j -= static_cast<float>(j) > ys;
  const float fx = xs - static_cast<float>(i), fy = ys - static_cast<float>(j);
  const int i0 = i & (w - 1), i1 = (i + 1) & (w - 1);
  const int j0 = j & (h - 1), j1 = (j + 1) & (h - 1);
  const float gx = 1.0f - fx, gy = 1.0f - fy;
  if (!level.decoded.empty()) {
    const float* row0 = &level.decoded[static_cast<std::size_t>(j0) * w * 4];
    const float* row1 = &level.decoded[static_cast<std::size_t>(j1) * w * 4];
    const Lanes4 wx0 = Lanes4::splat(gx), wx1 = Lanes4::splat(fx);
    const Lanes4 top = Lanes4::load(row0 + 4 * i0) * wx0 + Lanes4::load(row0 + 4 * i1) * wx1;
    const Lanes4 bottom = Lanes4::load(row1 + 4 * i0) * wx0 + Lanes4::load(row1 + 4 * i1) * wx1;
    out = (top * Lanes4::splat(gy) + bottom * Lanes4::splat(fy)).masked<kChannels>();
    return true;
  }
  const std::uint8_t* row0 = &level.rgba[static_cast<std::size_t>(j0) * w * 4];
  const std::uint8_t* row1 = &level.rgba[static_cast<std::size_t>(j1) * w * 4];
  const std::uint8_t *a = row0 + 4 * i0, *b = row0 + 4 * i1, *c = row1 + 4 * i0, *d = row1 + 4 * i1;
  float result[4];
  for (int k = 0; k < 3; ++k) {
    if (!((kChannels >> k) & 1u)) {
      result[k] = 0.0f;
      continue;
    }
    const float top = rgbTable[a[k]] * gx + rgbTable[b[k]] * fx;
    const float bottom = rgbTable[c[k]] * gx + rgbTable[d[k]] * fx;
    result[k] = top * gy + bottom * fy;
  }
  if constexpr ((kChannels & 8u) != 0) {
    const float top = alphaTable[a[3]] * gx + alphaTable[b[3]] * fx;
    const float bottom = alphaTable[c[3]] * gx + alphaTable[d[3]] * fx;
    result[3] = top * gy + bottom * fy;
  } else {
    result[3] = 0.0f;
  }
  // From registers (set, not a load of `result`: four scalar stores read back as one vector
  // would stall on store forwarding).
  out = Lanes4::set(result[0], result[1], result[2], result[3]);
  return true;
}

// Whether lookups of `sampler` with `filter` can take bilinearRepeatPow2.
bool repeatLinear(const TextureSampler& sampler, TextureFilter filter) {
  return filter == TextureFilter::Linear && sampler.wrapS == TextureWrap::Repeat &&
         sampler.wrapT == TextureWrap::Repeat;
}

// One level's lookup with `filter`: the fast path when it applies. alphaTable: tables().linear.
template <unsigned kChannels = 0xF>
[[gnu::always_inline]] inline glm::vec4 lookupLevel(const MipLevel& level, const float* rgbTable,
                                                    const float* alphaTable, const TextureSampler& sampler,
                                                    glm::vec2 uv, TextureFilter filter) {
  Lanes4 out;
  if (repeatLinear(sampler, filter) && bilinearRepeatPow2<kChannels>(level, rgbTable, alphaTable, uv, out)) {
    glm::vec4 value;
    out.store(value);
    return value;
  }
  return sampleLevel(level, rgbTable, sampler, uv, filter);
}

// KHR_texture_transform without building the matrix (no trigonometry for the common unrotated
// case); the same arithmetic as TextureTransform::matrix().
glm::vec2 applyTransform(const TextureTransform& transform, glm::vec2 uv) {
  const glm::vec2 scaled = uv * transform.scale;
  if (transform.rotation == 0.0f) return scaled + transform.offset;
  const float c = std::cos(transform.rotation), s = std::sin(transform.rotation);
  return glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + transform.offset;
}

}  // namespace

float srgbToLinear(std::uint8_t value) { return tables().srgb[value]; }

const float* srgbDecodeTable() { return tables().srgb.data(); }

MipChain buildMipChain(const TextureImage& image, ColorSpace colorSpace) {
  MipChain chain;
  chain.colorSpace = colorSpace;
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    return chain;
  MipLevel base;
  base.width = image.width;
  base.height = image.height;
  base.rgba = image.rgba;
  chain.levels.push_back(std::move(base));
  while (chain.levels.back().width > 1 || chain.levels.back().height > 1)
    chain.levels.push_back(reduce(chain.levels.back(), colorSpace));
  chain.alphaAllOne = std::all_of(chain.levels.begin(), chain.levels.end(), [](const MipLevel& level) {
    for (std::size_t i = 3; i < level.rgba.size(); i += 4)
      if (level.rgba[i] != 255) return false;
    return true;
  });
  return chain;
}

void decodeSmallLevels(MipChain& chain) {
  const float* rgbTable = chain.colorSpace == ColorSpace::Srgb ? tables().srgb.data() : tables().linear.data();
  const float* alphaTable = tables().linear.data();
  for (MipLevel& level : chain.levels) {
    if (static_cast<long long>(level.width) * level.height > kDecodedLevelTexels) continue;
    level.decoded.resize(level.rgba.size());
    for (std::size_t i = 0; i + 3 < level.rgba.size(); i += 4) {
      for (std::size_t c = 0; c < 3; ++c) level.decoded[i + c] = rgbTable[level.rgba[i + c]];
      level.decoded[i + 3] = alphaTable[level.rgba[i + 3]];
    }
  }
}

float textureLod(const MipChain& chain, float footprintUv) {
  if (!(footprintUv > 0.0f) || chain.levels.empty()) return -std::numeric_limits<float>::infinity();
  const float texels =
      footprintUv * std::sqrt(static_cast<float>(chain.width()) * static_cast<float>(chain.height()));
  return std::log2(texels);
}

int wrapTexel(int i, int size, TextureWrap wrap) {
  // GL 4.5 table 8.20.
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return std::clamp(i, 0, size - 1);
    case TextureWrap::MirroredRepeat: {
      // Power-of-two sizes (most textures) wrap by a mask (two's complement), without a division.
      int m = (size & (size - 1)) == 0 ? i & (2 * size - 1) : i % (2 * size);
      if (m < 0) m += 2 * size;
      const int a = m - size;
      const int mirrored = a >= 0 ? a : -(1 + a);
      return (size - 1) - mirrored;
    }
    case TextureWrap::Repeat:
    default: {
      if ((size & (size - 1)) == 0) return i & (size - 1);
      const int m = i % size;
      return m < 0 ? m + size : m;
    }
  }
}

namespace {

// sampleMipChain's body, inlined into SceneTextures::trySample too, so that the result is written
// where the caller wants it (returning a glm::vec4 packs it into two registers through the stack,
// a store-forwarding stall per lookup in perf annotate).
template <unsigned kChannels = 0xF>
[[gnu::always_inline]] inline void sampleChainInto(const MipChain& chain, const TextureSampler& sampler,
                                                   glm::vec2 uv, float lod, glm::vec4& out) {
  if (chain.levels.empty()) {
    out = glm::vec4(1.0f);
    return;
  }
  const DecodeTables& decode = tables();
  const float* rgbTable = chain.colorSpace == ColorSpace::Srgb ? decode.srgb.data() : decode.linear.data();
  const float* alphaTable = decode.linear.data();
  if (lod != lod) lod = 0.0f;
  // GL 4.5 section 8.14: lambda <= c magnifies, with c = 0 (iblkit takes c = 0 for every filter
  // pair; GL's c = 1/2 applies only to LINEAR magnification with a NEAREST_MIPMAP_* minification).
  if (lod <= 0.0f) {
    out = lookupLevel<kChannels>(chain.levels[0], rgbTable, alphaTable, sampler, uv, sampler.magFilter);
    return;
  }
  if (!sampler.mipmaps) {
    out = lookupLevel<kChannels>(chain.levels[0], rgbTable, alphaTable, sampler, uv, sampler.minFilter);
    return;
  }
  const int q = static_cast<int>(chain.levels.size()) - 1;
  if (sampler.mipFilter == TextureFilter::Nearest) {
    // Section 8.14.3: d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else the base level.
    const int d = lod <= 0.5f ? 0 : std::min(q, static_cast<int>(std::ceil(std::min(lod, 1e6f) + 0.5f)) - 1);
    out = lookupLevel<kChannels>(chain.levels[d], rgbTable, alphaTable, sampler, uv, sampler.minFilter);
    return;
  }
  if (lod >= static_cast<float>(q)) {
    out = lookupLevel<kChannels>(chain.levels[q], rgbTable, alphaTable, sampler, uv, sampler.minFilter);
    return;
  }
  const int d1 = static_cast<int>(std::floor(lod));
  const float fraction = lod - static_cast<float>(d1);
  if (fraction != 0.0f && repeatLinear(sampler, sampler.minFilter)) {
    // Trilinear in registers: blending two vec4 results went through the stack with a
    // store-forwarding stall per lookup (perf). The same arithmetic as glm::mix below.
    Lanes4 a, b;
    if (bilinearRepeatPow2<kChannels>(chain.levels[d1], rgbTable, alphaTable, uv, a) &&
        bilinearRepeatPow2<kChannels>(chain.levels[d1 + 1], rgbTable, alphaTable, uv, b)) {
      (a * Lanes4::splat(1.0f - fraction) + b * Lanes4::splat(fraction)).store(out);
      return;
    }
  }
  const glm::vec4 a =
      lookupLevel<kChannels>(chain.levels[d1], rgbTable, alphaTable, sampler, uv, sampler.minFilter);
  if (fraction == 0.0f) {
    out = a;
    return;
  }
  const glm::vec4 b =
      lookupLevel<kChannels>(chain.levels[d1 + 1], rgbTable, alphaTable, sampler, uv, sampler.minFilter);
  out = glm::mix(a, b, fraction);
}

}  // namespace

glm::vec4 sampleMipChain(const MipChain& chain, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  glm::vec4 out;
  sampleChainInto(chain, sampler, uv, lod, out);
  return out;
}

SceneTextures::SceneTextures(const std::vector<Texture>& textures, const std::vector<TextureImage>& images,
                             const std::vector<Material>& materials) {
  textures_.resize(textures.size());
  for (std::size_t t = 0; t < textures.size(); ++t) textures_[t].sampler = textures[t].sampler;
  // Chains are per (image, colour space): two textures over one image share them.
  std::vector<int> linearChainOfImage(images.size(), -1), srgbChainOfImage(images.size(), -1);
  auto use = [&](const TextureRef& ref, ColorSpace colorSpace) {
    if (!ref.present() || ref.texture >= static_cast<int>(textures.size())) return;
    const int image = textures[ref.texture].image;
    if (image < 0 || image >= static_cast<int>(images.size())) return;
    std::vector<int>& chainOfImage = colorSpace == ColorSpace::Srgb ? srgbChainOfImage : linearChainOfImage;
    if (chainOfImage[image] < 0) {
      MipChain chain = buildMipChain(images[image], colorSpace);
      if (chain.levels.empty()) return;
      decodeSmallLevels(chain);
      chainOfImage[image] = static_cast<int>(chains_.size());
      chainLog2Size_.push_back(
          0.5f * std::log2(static_cast<float>(chain.width()) * static_cast<float>(chain.height())));
      chains_.push_back(std::move(chain));
    }
    Entry& entry = textures_[ref.texture];
    (colorSpace == ColorSpace::Srgb ? entry.srgb : entry.linear) = chainOfImage[image];
  };
  for (const Material& material : materials) {
    use(material.baseColorTexture, ColorSpace::Srgb);
    use(material.metallicRoughnessTexture, ColorSpace::Linear);
    use(material.normalTexture, ColorSpace::Linear);
    use(material.occlusionTexture, ColorSpace::Linear);
    use(material.emissiveTexture, ColorSpace::Srgb);
  }
}

const MipChain* SceneTextures::chain(int texture, ColorSpace colorSpace) const {
  if (texture < 0 || texture >= static_cast<int>(textures_.size())) return nullptr;
  const int index = colorSpace == ColorSpace::Srgb ? textures_[texture].srgb : textures_[texture].linear;
  return index < 0 ? nullptr : &chains_[index];
}

const TextureSampler& SceneTextures::sampler(int texture) const {
  static const TextureSampler defaults;
  if (texture < 0 || texture >= static_cast<int>(textures_.size())) return defaults;
  return textures_[texture].sampler;
}

float SceneTextures::log2Footprint(float footprintUv) {
  return footprintUv > 0.0f ? std::log2(footprintUv) : -std::numeric_limits<float>::infinity();
}

bool SceneTextures::trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                              float log2FootprintUv, glm::vec4& value) const {
  return trySampleChannels<kRgba>(ref, colorSpace, uv, log2FootprintUv, value);
}

bool SceneTextures::trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                              float log2FootprintUv, glm::vec4& value, unsigned channels) const {
  switch (channels) {
    case kRed:
      return trySampleChannels<kRed>(ref, colorSpace, uv, log2FootprintUv, value);
    case kGreenBlue:
      return trySampleChannels<kGreenBlue>(ref, colorSpace, uv, log2FootprintUv, value);
    case kRgb:
      return trySampleChannels<kRgb>(ref, colorSpace, uv, log2FootprintUv, value);
    case kAlpha:
      return trySampleChannels<kAlpha>(ref, colorSpace, uv, log2FootprintUv, value);
    default:
      return trySampleChannels<kRgba>(ref, colorSpace, uv, log2FootprintUv, value);
  }
}

template <unsigned kChannels>
bool SceneTextures::trySampleChannels(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                                      float log2FootprintUv, glm::vec4& value) const {
  if (ref.texture < 0 || ref.texture >= static_cast<int>(textures_.size())) return false;
  const Entry& entry = textures_[ref.texture];
  const int index = colorSpace == ColorSpace::Srgb ? entry.srgb : entry.linear;
  if (index < 0) return false;
  // textureLod's log2(footprint * sqrt(width * height)) as a sum of logs (equal up to rounding).
  // The transform scales the footprint as it scales uv (isotropically: the geometric mean).
  float lod = log2FootprintUv + chainLog2Size_[index];
  const glm::vec2 scale = ref.transform.scale;
  if (scale.x != 1.0f || scale.y != 1.0f) {
    const float area = std::abs(scale.x * scale.y);
    lod += area > 0.0f ? 0.5f * std::log2(area) : -std::numeric_limits<float>::infinity();
  }
  if (lod != lod) lod = -std::numeric_limits<float>::infinity();  // -inf + inf: a zero footprint
  sampleChainInto<kChannels>(chains_[index], entry.sampler, applyTransform(ref.transform, uv), lod, value);
  return true;
}

glm::vec4 SceneTextures::sample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                                float footprintUv) const {
  glm::vec4 value(1.0f);
  trySample(ref, colorSpace, uv, log2Footprint(footprintUv), value);
  return value;
}

}  // namespace iblkit
