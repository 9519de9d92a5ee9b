#include "core/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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
  // Lanes4(...).masked<kChannels>() with the channels given at run time.
  Lanes4 maskedBy(unsigned channels) const {
    alignas(16) static constexpr std::int32_t kKeep[16][4] = {
        {0, 0, 0, 0},   {-1, 0, 0, 0},   {0, -1, 0, 0},   {-1, -1, 0, 0},  {0, 0, -1, 0},  {-1, 0, -1, 0},
        {0, -1, -1, 0}, {-1, -1, -1, 0}, {0, 0, 0, -1},   {-1, 0, 0, -1},  {0, -1, 0, -1}, {-1, -1, 0, -1},
        {0, 0, -1, -1}, {-1, 0, -1, -1}, {0, -1, -1, -1}, {-1, -1, -1, -1}};
    return {_mm_and_ps(v, _mm_load_ps(reinterpret_cast<const float*>(kKeep[channels & 0xFu])))};
  }
  void store(glm::vec4& out) const { _mm_storeu_ps(&out.x, v); }
#else
  float v[4];
  static Lanes4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static Lanes4 set(float x, float y, float z, float w) { return {{x, y, z, w}}; }
  static Lanes4 splat(float x) { return {{x, x, x, x}}; }
  friend Lanes4 operator*(Lanes4 a, Lanes4 b) {
    return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}};
  }
  friend Lanes4 operator+(Lanes4 a, Lanes4 b) {
    return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}};
  }
  template <unsigned kChannels>
  Lanes4 masked() const {
    Lanes4 out = *this;
    for (int k = 0; k < 4; ++k)
      if (!((kChannels >> k) & 1u)) out.v[k] = 0.0f;
    return out;
  }
  Lanes4 maskedBy(unsigned channels) const {
    Lanes4 out = *this;
    for (int k = 0; k < 4; ++k)
      if (!((channels >> k) & 1u)) out.v[k] = 0.0f;
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

// The 2 x 2 texels of sampleLevel's LINEAR lookup and their weights in the common case, worked
// out once and read from any level of the same size: both wraps REPEAT on power-of-two sizes (a
// mask, no switch) and the coordinate well inside int range. The same texels and weights as
// sampleLevel, and blendTaps the same arithmetic order, so the same result.
struct BilinearTaps {
  // 4 (y * width + x) of (i0, j0), (i1, j0), (i0, j1), (i1, j1): the texel's first element in
  // both rgba (bytes) and decoded (floats), so that a load's address is one addressing mode.
  std::size_t texel[4];
  float fx, fy;
  Lanes4 wx0, wx1, wy0, wy1;  // 1 - fx, fx, 1 - fy, fy in every lane (decoded levels' blend)
};

// Whether lookups of `sampler` with `filter` can take repeatPow2Taps.
bool repeatLinear(const TextureSampler& sampler, TextureFilter filter) {
  return filter == TextureFilter::Linear && sampler.wrapS == TextureWrap::Repeat &&
         sampler.wrapT == TextureWrap::Repeat;
}

// The taps at `uv` of a w x h level for a REPEAT LINEAR lookup; false for a size that is not a
// power of two or a coordinate beyond 2^24 texels (or NaN), which then take sampleLevel.
[[gnu::always_inline]] inline bool repeatPow2Taps(int w, int h, glm::vec2 uv, BilinearTaps& taps) {
  if (((w & (w - 1)) | (h & (h - 1))) != 0) return false;
  const float xs = uv.x * w - 0.5f, ys = uv.y * h - 0.5f;
  if (!(std::abs(xs) < 16777216.0f && std::abs(ys) < 16777216.0f)) return false;  // NaN, inf, huge
  // floor without libm's call (std::floor is not inlined without SSE4.1): truncate, then step
  // down for negative non-integers; exact for |x| < 2^24.
  int i = static_cast<int>(xs), j = static_cast<int>(ys);
  i -= static_cast<float>(i) > xs;
  j -= static_cast<float>(j) > ys;
  taps.fx = xs - static_cast<float>(i);
  taps.fy = ys - static_cast<float>(j);
  taps.wx0 = Lanes4::splat(1.0f - taps.fx);
  taps.wx1 = Lanes4::splat(taps.fx);
  taps.wy0 = Lanes4::splat(1.0f - taps.fy);
  taps.wy1 = Lanes4::splat(taps.fy);
  const std::size_t i0 = static_cast<std::size_t>(i & (w - 1)),
                    i1 = static_cast<std::size_t>((i + 1) & (w - 1));
  const std::size_t row0 = static_cast<std::size_t>(j & (h - 1)) * static_cast<std::size_t>(w);
  const std::size_t row1 = static_cast<std::size_t>((j + 1) & (h - 1)) * static_cast<std::size_t>(w);
  taps.texel[0] = 4 * (row0 + i0);
  taps.texel[1] = 4 * (row0 + i1);
  taps.texel[2] = 4 * (row1 + i0);
  taps.texel[3] = 4 * (row1 + i1);
  return true;
}

// The bilinear blend of `level`'s texels at `taps` (sampleLevel's weights and order: the rows in
// x, then the two rows in y), inlined into the lookups (a call per level returned the vec4 through
// the stack, and the perf profile showed the stall). kChannels (SceneTextures::kRgba ...): the
// channels computed, the others 0. A level with decoded texels loads each texel's four channels
// at once (the tables' decodings) into one Lanes4; otherwise each used channel's four bytes are
// decoded through the tables and the other channels' texels are not loaded.
[[gnu::always_inline]] inline Lanes4 blendDecoded(const MipLevel& level, const BilinearTaps& taps) {
  const float* texels = level.decoded.data();
  const Lanes4 top = Lanes4::load(texels + taps.texel[0]) * taps.wx0 + Lanes4::load(texels + taps.texel[1]) * taps.wx1;
  const Lanes4 bottom =
      Lanes4::load(texels + taps.texel[2]) * taps.wx0 + Lanes4::load(texels + taps.texel[3]) * taps.wx1;
  return top * taps.wy0 + bottom * taps.wy1;
}

template <unsigned kChannels = 0xF>
[[gnu::always_inline]] inline Lanes4 blendTaps(const MipLevel& level, const float* rgbTable,
                                               const float* alphaTable, const BilinearTaps& taps) {
  if (!level.decoded.empty()) return blendDecoded(level, taps).masked<kChannels>();
  const float fx = taps.fx, fy = taps.fy, gx = 1.0f - fx, gy = 1.0f - fy;
  const std::uint8_t* texels = level.rgba.data();
  const std::uint8_t *a = texels + taps.texel[0], *b = texels + taps.texel[1], *c = texels + taps.texel[2],
                     *d = texels + taps.texel[3];
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
  return Lanes4::set(result[0], result[1], result[2], result[3]);
}

// GL 4.5 section 8.14's choice of levels for lambda = `lod`: `level` alone (fraction 0) or
// blended with level + 1 by `fraction` (LINEAR_MIPMAP_LINEAR), each read with `filter`.
struct LevelChoice {
  int level;
  float fraction;
  TextureFilter filter;
};

[[gnu::always_inline]] inline LevelChoice chooseLevels(const MipChain& chain, const TextureSampler& sampler,
                                                       float lod) {
  if (lod != lod) lod = 0.0f;
  // Section 8.14: lambda <= c magnifies, with c = 0 (iblkit takes c = 0 for every filter pair;
  // GL's c = 1/2 applies only to LINEAR magnification with a NEAREST_MIPMAP_* minification).
  if (lod <= 0.0f) return {0, 0.0f, sampler.magFilter};
  if (!sampler.mipmaps) return {0, 0.0f, sampler.minFilter};
  const int q = static_cast<int>(chain.levels.size()) - 1;
  if (sampler.mipFilter == TextureFilter::Nearest) {
    // Section 8.14.3: d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else the base level.
    const int d = lod <= 0.5f ? 0 : std::min(q, static_cast<int>(std::ceil(std::min(lod, 1e6f) + 0.5f)) - 1);
    return {d, 0.0f, sampler.minFilter};
  }
  if (lod >= static_cast<float>(q)) return {q, 0.0f, sampler.minFilter};
  // floor(lod) for 0 < lod < q: truncation (std::floor is a libm call or a long SSE2 sequence
  // without SSE4.1).
  const int d1 = static_cast<int>(lod);
  return {d1, lod - static_cast<float>(d1), sampler.minFilter};
}

// A lookup worked out before any texel is read: its levels, and on the fast path (REPEAT LINEAR
// power-of-two, repeatPow2Taps) the taps in each. It depends on the chain only through its level
// sizes, so lookups of several chains of one size at one uv and lod share it (sampleSlots).
struct LookupPlan {
  LevelChoice choice;
  bool fast;
  BilinearTaps taps[2];
  Lanes4 w0, w1;  // 1 - fraction, fraction in every lane (the fast trilinear blend)
};

[[gnu::always_inline]] inline LookupPlan planLookup(const MipChain& chain, const TextureSampler& sampler,
                                                    glm::vec2 uv, float lod) {
  LookupPlan plan;
  plan.fast = false;
  if (chain.levels.empty()) {
    plan.choice = LevelChoice{};
    return plan;
  }
  plan.choice = chooseLevels(chain, sampler, lod);
  const int d = plan.choice.level;
  plan.fast = repeatLinear(sampler, plan.choice.filter) &&
              repeatPow2Taps(chain.levels[d].width, chain.levels[d].height, uv, plan.taps[0]) &&
              (plan.choice.fraction == 0.0f ||
               repeatPow2Taps(chain.levels[d + 1].width, chain.levels[d + 1].height, uv, plan.taps[1]));
  plan.w0 = Lanes4::splat(1.0f - plan.choice.fraction);
  plan.w1 = Lanes4::splat(plan.choice.fraction);
  return plan;
}

// The lookup `plan` (made for a chain of `chain`'s level sizes at `uv`) in `chain`, written to
// `out` (returning a glm::vec4 packs it into two registers through the stack, a store-forwarding
// stall per lookup in perf annotate). An empty chain reads 1.
template <unsigned kChannels = 0xF>
[[gnu::always_inline]] inline void runLookup(const MipChain& chain, const DecodeTables& decode,
                                             const TextureSampler& sampler, glm::vec2 uv,
                                             const LookupPlan& plan, glm::vec4& out) {
  if (chain.levels.empty()) {
    out = glm::vec4(1.0f);
    return;
  }
  const float* rgbTable = chain.colorSpace == ColorSpace::Srgb ? decode.srgb.data() : decode.linear.data();
  const float* alphaTable = decode.linear.data();
  const int d = plan.choice.level;
  const float fraction = plan.choice.fraction;
  if (plan.fast) {
    const Lanes4 a = blendTaps<kChannels>(chain.levels[d], rgbTable, alphaTable, plan.taps[0]);
    if (fraction == 0.0f) {
      a.store(out);
      return;
    }
    // Trilinear in registers, the arithmetic of glm::mix below.
    const Lanes4 b = blendTaps<kChannels>(chain.levels[d + 1], rgbTable, alphaTable, plan.taps[1]);
    (a * plan.w0 + b * plan.w1).store(out);
    return;
  }
  const glm::vec4 a = sampleLevel(chain.levels[d], rgbTable, sampler, uv, plan.choice.filter);
  out = fraction == 0.0f
            ? a
            : glm::mix(a, sampleLevel(chain.levels[d + 1], rgbTable, sampler, uv, plan.choice.filter),
                       fraction);
}

// The fast lookup `plan` on decoded levels (levels[plan level] and, trilinear, the next), the
// channels outside `channels` 0: runLookupChannels' and SlotSet::sample's common case.
[[gnu::always_inline]] inline void storeDecodedLookup(const MipLevel* levels, const LookupPlan& plan,
                                                      unsigned channels, glm::vec4& out) {
  const int d = plan.choice.level;
  const Lanes4 a = blendDecoded(levels[d], plan.taps[0]);
  (plan.choice.fraction == 0.0f ? a : a * plan.w0 + blendDecoded(levels[d + 1], plan.taps[1]) * plan.w1)
      .maskedBy(channels)
      .store(out);
}

// runLookup with the channel mask given at run time (SceneTextures's masks). The common case, the
// fast path on decoded levels (a level's smaller ones are decoded too), is one code path for every
// mask: blendTaps' decoded blend, the mask applied at the end.
[[gnu::always_inline]] inline void runLookupChannels(unsigned channels, const MipChain& chain,
                                                     const DecodeTables& decode,
                                                     const TextureSampler& sampler, glm::vec2 uv,
                                                     const LookupPlan& plan, glm::vec4& out) {
  // The plan's level decoded means d + 1 is too (MipChain::decodedFrom).
  if (plan.fast && plan.choice.level >= chain.decodedFrom) return storeDecodedLookup(chain.levels.data(), plan, channels, out);
  switch (channels) {
    case SceneTextures::kRed:
      return runLookup<SceneTextures::kRed>(chain, decode, sampler, uv, plan, out);
    case SceneTextures::kGreenBlue:
      return runLookup<SceneTextures::kGreenBlue>(chain, decode, sampler, uv, plan, out);
    case SceneTextures::kRgb:
      return runLookup<SceneTextures::kRgb>(chain, decode, sampler, uv, plan, out);
    case SceneTextures::kAlpha:
      return runLookup<SceneTextures::kAlpha>(chain, decode, sampler, uv, plan, out);
    default:
      return runLookup<SceneTextures::kRgba>(chain, decode, sampler, uv, plan, out);
  }
}

bool sameSampler(const TextureSampler& a, const TextureSampler& b) {
  return a.wrapS == b.wrapS && a.wrapT == b.wrapT && a.magFilter == b.magFilter &&
         a.minFilter == b.minFilter && a.mipmaps == b.mipmaps && a.mipFilter == b.mipFilter;
}

// Bit for bit: equal transforms then give equal uvs and lods (== would also match -0 with 0).
bool sameTransform(const TextureTransform& a, const TextureTransform& b) {
  static_assert(sizeof(TextureTransform) == 5 * sizeof(float));
  return std::memcmp(&a, &b, sizeof(TextureTransform)) == 0;
}

// The level of detail of a lookup from its terms: textureLod's log2(footprint * sqrt(width *
// height)) as a sum of logs (equal up to rounding), log2FootprintUv + log2Size, plus log2Scale
// when the transform scales (`scaled`): it scales the footprint as it scales uv (isotropically:
// the geometric mean, log2TransformScale). -inf for -inf + inf (a zero footprint).
float lodFromTerms(float log2FootprintUv, float log2Size, bool scaled, float log2Scale) {
  float lod = log2FootprintUv + log2Size;
  if (scaled) lod += log2Scale;
  if (lod != lod) lod = -std::numeric_limits<float>::infinity();
  return lod;
}
bool scalesFootprint(const TextureTransform& transform) {
  return transform.scale.x != 1.0f || transform.scale.y != 1.0f;
}
float log2TransformScale(const TextureTransform& transform) {
  const float area = std::abs(transform.scale.x * transform.scale.y);
  return area > 0.0f ? 0.5f * std::log2(area) : -std::numeric_limits<float>::infinity();
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
  const float* rgbTable =
      chain.colorSpace == ColorSpace::Srgb ? tables().srgb.data() : tables().linear.data();
  const float* alphaTable = tables().linear.data();
  for (std::size_t l = 0; l < chain.levels.size(); ++l) {
    MipLevel& level = chain.levels[l];
    if (static_cast<long long>(level.width) * level.height > kDecodedLevelTexels) continue;
    chain.decodedFrom = std::min(chain.decodedFrom, static_cast<int>(l));
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

glm::vec4 sampleMipChain(const MipChain& chain, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  glm::vec4 out;
  runLookup(chain, tables(), sampler, uv, planLookup(chain, sampler, uv, lod), out);
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
  for (std::size_t t = 0; t < textures_.size(); ++t) {
    Entry& entry = textures_[t];
    const int chain = entry.linear >= 0 ? entry.linear : entry.srgb;
    if (chain < 0) continue;
    entry.layout = static_cast<int>(t);
    for (std::size_t other = 0; other < t; ++other) {
      const Entry& earlier = textures_[other];
      const int otherChain = earlier.linear >= 0 ? earlier.linear : earlier.srgb;
      if (otherChain >= 0 && sameSampler(earlier.sampler, entry.sampler) &&
          chains_[otherChain].width() == chains_[chain].width() &&
          chains_[otherChain].height() == chains_[chain].height()) {
        entry.layout = earlier.layout;
        break;
      }
    }
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

int SceneTextures::chainIndex(const TextureRef& ref, ColorSpace colorSpace) const {
  if (ref.texture < 0 || ref.texture >= static_cast<int>(textures_.size())) return -1;
  const Entry& entry = textures_[ref.texture];
  return colorSpace == ColorSpace::Srgb ? entry.srgb : entry.linear;
}

float SceneTextures::slotLod(const TextureRef& ref, int chain, float log2FootprintUv) const {
  const bool scaled = scalesFootprint(ref.transform);
  return lodFromTerms(log2FootprintUv, chainLog2Size_[chain], scaled, scaled ? log2TransformScale(ref.transform) : 0.0f);
}

bool SceneTextures::trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                              float log2FootprintUv, glm::vec4& value) const {
  return trySample(ref, colorSpace, uv, log2FootprintUv, value, kRgba);
}

bool SceneTextures::trySample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                              float log2FootprintUv, glm::vec4& value, unsigned channels) const {
  const int index = chainIndex(ref, colorSpace);
  if (index < 0) return false;
  const MipChain& chain = chains_[index];
  const TextureSampler& sampler = textures_[ref.texture].sampler;
  const glm::vec2 transformed = applyTransform(ref.transform, uv);
  runLookupChannels(channels, chain, tables(), sampler, transformed,
                    planLookup(chain, sampler, transformed, slotLod(ref, index, log2FootprintUv)), value);
  return true;
}

SceneTextures::SlotSet::SlotSet(const SceneTextures& textures, const SlotLookup* lookups, int count) {
  count = std::min(count, kMaxLookups);
  // Each lookup's group: a later one of the same layout (SceneTextures::Entry), uv set and
  // transform (so the same transformed uv and lod) joins an earlier one's.
  int groupOf[kMaxLookups];
  int ref[kMaxLookups];  // lookups[l]'s chain index, -1 for none
  for (int l = 0; l < count; ++l) {
    const TextureRef& r = *lookups[l].ref;
    ref[l] = textures.chainIndex(r, lookups[l].colorSpace);
    groupOf[l] = -1;
    if (ref[l] < 0) continue;
    found_ |= 1u << l;
    const Entry& entry = textures.textures_[r.texture];
    const int set = r.texCoord == 1 ? 1 : 0;
    for (int g = 0; g < groupCount_ && groupOf[l] < 0; ++g) {
      const Group& candidate = groups_[g];
      if (candidate.layout == entry.layout && candidate.set == set && sameTransform(candidate.transform, r.transform))
        groupOf[l] = g;
    }
    if (groupOf[l] >= 0) continue;
    Group& made = groups_[groupCount_];
    groupOf[l] = groupCount_++;
    made.set = set;
    made.transform = r.transform;
    made.sampler = entry.sampler;
    made.sizes = &textures.chains_[static_cast<std::size_t>(ref[l])];
    made.log2Size = textures.chainLog2Size_[static_cast<std::size_t>(ref[l])];
    made.scaled = scalesFootprint(r.transform);
    if (made.scaled) made.log2Scale = log2TransformScale(r.transform);
    made.layout = entry.layout;
  }
  // The slots in group order.
  int slots = 0;
  for (int g = 0; g < groupCount_; ++g) {
    Group& group = groups_[g];
    group.first = slots;
    for (int l = 0; l < count; ++l) {
      if (groupOf[l] != g) continue;
      Slot& slot = slots_[slots++];
      slot.chain = &textures.chains_[static_cast<std::size_t>(ref[l])];
      slot.channels = lookups[l].channels;
      slot.lookup = l;
      group.lookups |= 1u << l;
    }
    group.count = slots - group.first;
  }
}

void SceneTextures::SlotSet::sample(const glm::vec2 texcoords[2], const float footprintUv[2], glm::vec4* values,
                                    unsigned active) const {
  const DecodeTables& decode = tables();
  float log2Footprints[2];
  bool haveLog2[2] = {false, false};
  for (int g = 0; g < groupCount_; ++g) {
    const Group& group = groups_[g];
    if (!(group.lookups & active)) continue;
    const int set = group.set;
    if (!haveLog2[set]) {
      log2Footprints[set] = log2Footprint(footprintUv[set]);
      haveLog2[set] = true;
    }
    const float lod = lodFromTerms(log2Footprints[set], group.log2Size, group.scaled, group.log2Scale);
    const glm::vec2 uv = applyTransform(group.transform, texcoords[set]);
    const LookupPlan plan = planLookup(*group.sizes, group.sampler, uv, lod);
    // runLookupChannels' decoded fast path, decided once for the group: its chains have the same
    // level sizes, so the same decoded levels (MipChain::decodedFrom).
    const int d = plan.choice.level;
    if (plan.fast && d >= group.sizes->decodedFrom) {
      for (int s = group.first; s < group.first + group.count; ++s) {
        const Slot& slot = slots_[s];
        if ((active >> slot.lookup) & 1u)
          storeDecodedLookup(slot.chain->levels.data(), plan, slot.channels, values[slot.lookup]);
      }
      continue;
    }
    for (int s = group.first; s < group.first + group.count; ++s) {
      const Slot& slot = slots_[s];
      if (!((active >> slot.lookup) & 1u)) continue;
      runLookupChannels(slot.channels, *slot.chain, decode, group.sampler, uv, plan, values[slot.lookup]);
    }
  }
}

void SceneTextures::sampleSlots(SlotLookup* lookups, int count, const glm::vec2 texcoords[2],
                                const float footprintUv[2]) const {
  for (int begin = 0; begin < count; begin += SlotSet::kMaxLookups) {
    const int n = std::min(count - begin, SlotSet::kMaxLookups);
    SlotLookup* chunk = lookups + begin;
    const SlotSet set(*this, chunk, n);
    glm::vec4 values[SlotSet::kMaxLookups];
    for (int l = 0; l < n; ++l) values[l] = chunk[l].value;
    set.sample(texcoords, footprintUv, values);
    for (int l = 0; l < n; ++l) {
      chunk[l].found = set.found(l);
      chunk[l].value = values[l];
    }
  }
}

glm::vec4 SceneTextures::sample(const TextureRef& ref, ColorSpace colorSpace, glm::vec2 uv,
                                float footprintUv) const {
  glm::vec4 value(1.0f);
  trySample(ref, colorSpace, uv, log2Footprint(footprintUv), value);
  return value;
}

}  // namespace iblkit
