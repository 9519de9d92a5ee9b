// FLIP written from the papers (see flip.h): the HPG 2020 paper's colour pipeline and feature
// pipeline, and Ray Tracing Gems II (RTG2) chapter 19 for HDR-FLIP.
#include "score/flip.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"

namespace iblkit {

namespace {

// One channel of an image, row-major, row 0 at the top.
struct Plane {
  int width = 0, height = 0;
  std::vector<float> values;
  Plane(int w, int h)
      : width(w), height(h), values(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}
  float& operator[](std::size_t i) { return values[i]; }
  float operator[](std::size_t i) const { return values[i]; }
};

// Convolves with the separable kernel horizontal ⊗ vertical (both of odd length, centred), with the
// image's border pixels repeated outside it. Separable filtering with clamped coordinates equals the
// 2D filtering with clamped coordinates, so this is exact for every filter below.
// Both passes run along rows, one tap at a time over a whole row, so the inner loops are
// contiguous and vectorise; each output still adds its taps in tap order, the same sums bit for bit
// as a loop over the taps per pixel.
Plane convolveSeparable(const Plane& in, const std::vector<float>& horizontal,
                        const std::vector<float>& vertical) {
  const int w = in.width, h = in.height;
  const int rx = static_cast<int>(horizontal.size()) / 2, ry = static_cast<int>(vertical.size()) / 2;
  const std::size_t width = static_cast<std::size_t>(w);
  const auto row = [width](auto& plane, int y) {
    return plane.values.data() + static_cast<std::size_t>(y) * width;
  };
  Plane rows(w, h), out(w, h);
  // Horizontal: a padded copy of the row (its end pixels repeated), so the taps need no clamping.
  std::vector<float> padded(width + 2 * static_cast<std::size_t>(rx));
  for (int y = 0; y < h; ++y) {
    for (int x = -rx; x < w + rx; ++x)
      padded[static_cast<std::size_t>(x + rx)] = row(in, y)[std::clamp(x, 0, w - 1)];
    float* sum = row(rows, y);
    for (std::size_t i = 0; i < horizontal.size(); ++i) {
      const float tap = horizontal[i];
      const float* source = padded.data() + i;
      for (std::size_t x = 0; x < width; ++x) sum[x] += tap * source[x];
    }
  }
  // Vertical: each output row adds the rows above and below it (clamped at the borders), tap by tap.
  for (int y = 0; y < h; ++y) {
    float* sum = row(out, y);
    for (std::size_t j = 0; j < vertical.size(); ++j) {
      const float tap = vertical[j];
      const float* source = row(rows, std::clamp(y + static_cast<int>(j) - ry, 0, h - 1));
      for (std::size_t x = 0; x < width; ++x) sum[x] += tap * source[x];
    }
  }
  return out;
}

// Linear Rec.709 / sRGB primaries with the D65 white (IEC 61966-2-1, the XYZ <-> RGB matrices).
glm::vec3 linearRgbToXyz(const glm::vec3& rgb) {
  return {0.4124564f * rgb.r + 0.3575761f * rgb.g + 0.1804375f * rgb.b,
          0.2126729f * rgb.r + 0.7151522f * rgb.g + 0.0721750f * rgb.b,
          0.0193339f * rgb.r + 0.1191920f * rgb.g + 0.9503041f * rgb.b};
}
glm::vec3 xyzToLinearRgb(const glm::vec3& xyz) {
  return {3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
          -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
          0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z};
}
// The reference white: XYZ of linear RGB (1, 1, 1).
const glm::vec3 kWhite = linearRgbToXyz(glm::vec3(1.0f));

// YCxCz, the linearised CIELAB opponent space of Flohr et al. (colour pipeline): L* without the cube
// root, so that spatial filtering in it is meaningful.
glm::vec3 xyzToYcxcz(const glm::vec3& xyz) {
  const glm::vec3 n = xyz / kWhite;
  return {116.0f * n.y - 16.0f, 500.0f * (n.x - n.y), 200.0f * (n.y - n.z)};
}
glm::vec3 ycxczToXyz(const glm::vec3& ycxcz) {
  const float y = (ycxcz.x + 16.0f) / 116.0f;
  return glm::vec3(y + ycxcz.y / 500.0f, y, y - ycxcz.z / 200.0f) * kWhite;
}
// CIE 1976 L*a*b* (CIE 15:2004, section 8.2.1).
glm::vec3 xyzToLab(const glm::vec3& xyz) {
  constexpr float kDelta = 6.0f / 29.0f;
  const auto f = [&](float t) {
    return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0f * kDelta * kDelta) + 4.0f / 29.0f;
  };
  const glm::vec3 n = xyz / kWhite;
  const float fx = f(n.x), fy = f(n.y), fz = f(n.z);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}
// The Hunt effect (colour pipeline): chroma appears weaker at low luminance, so a* and b* are scaled
// by 0.01 L*.
glm::vec3 huntAdjust(const glm::vec3& lab) { return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z}; }
// HyAB (Abasi et al. 2020): city-block distance in lightness plus Euclidean distance in chroma,
// better than Euclidean Delta E for large colour differences (colour pipeline).
float hyab(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = a - b;
  return std::abs(d.x) + std::sqrt(d.y * d.y + d.z * d.z);
}

// Error exponent of the colour pipeline and the colour error mapping's knee (colour pipeline):
// differences below pc * cmax are compressed to [0, pt), the rest expanded to [pt, 1].
constexpr float kColorExponent = 0.7f;  // qc
constexpr float kKneeFraction = 0.4f;   // pc
constexpr float kKneeError = 0.95f;     // pt
// Feature detection (feature pipeline): the Gaussian derivative filters' width in degrees and the
// feature error's exponent.
constexpr float kFeatureWidthDegrees = 0.082f;  // w
constexpr float kFeatureExponent = 0.5f;        // qf

// The contrast sensitivity functions as spatial filters (colour pipeline): per
// channel of YCxCz a sum of two Gaussians a_k sqrt(pi / b_k) exp(-pi^2 x^2 / b_k), x in degrees.
struct CsfTerm {
  float a, b;
};
struct ChannelCsf {
  CsfTerm terms[2];
};
constexpr ChannelCsf kCsf[3] = {
    {{{1.0f, 0.0047f}, {0.0f, 1e-5f}}},   // achromatic
    {{{1.0f, 0.0053f}, {0.0f, 1e-5f}}},   // red-green
    {{{34.1f, 0.04f}, {13.5f, 0.025f}}},  // blue-yellow
};

// Filters one YCxCz channel with its CSF, normalised to unit sum. Every channel uses the same
// radius, three standard deviations of the widest Gaussian (b = 0.04, sigma^2 = b / (2 pi^2)).
Plane filterWithCsf(const Plane& channel, const ChannelCsf& csf, float pixelsPerDegree) {
  constexpr double kPi2 = std::numbers::pi * std::numbers::pi;
  const double widestSigma = std::sqrt(0.04 / (2.0 * kPi2));
  const int radius = static_cast<int>(std::ceil(3.0 * widestSigma * pixelsPerDegree));
  // The 2D kernel is sum_k A_k g_k(x) g_k(y), so its total is sum_k A_k (sum g_k)^2.
  struct Separable {
    double amplitude;
    std::vector<float> taps;
    double tapSum;
  };
  std::vector<Separable> parts;
  double total = 0.0;
  for (const CsfTerm& term : csf.terms) {
    if (term.a == 0.0f) continue;
    Separable part{term.a * std::sqrt(std::numbers::pi / term.b), {}, 0.0};
    for (int i = -radius; i <= radius; ++i) {
      const double x = i / double(pixelsPerDegree);
      const double g = std::exp(-kPi2 * x * x / term.b);
      part.taps.push_back(static_cast<float>(g));
      part.tapSum += g;
    }
    total += part.amplitude * part.tapSum * part.tapSum;
    parts.push_back(std::move(part));
  }
  Plane result(channel.width, channel.height);
  for (Separable& part : parts) {
    // Put the term's share of the normalisation into one of the two passes.
    const double scale = part.amplitude / total;
    std::vector<float> scaled = part.taps;
    for (float& t : scaled) t = static_cast<float>(t * scale);
    const Plane filtered = convolveSeparable(channel, scaled, part.taps);
    for (std::size_t i = 0; i < result.values.size(); ++i) result[i] += filtered[i];
  }
  return result;
}

// The edge and point detectors (feature pipeline): first and second derivatives of a Gaussian with
// sigma = w / 2 degrees, each normalised so that its positive weights sum to 1 and its negative
// weights to -1. The 2D filters are h(x) g(y) (and transposed), so they are separable: h is
// normalised by its positive and negative sums, g by its sum.
struct FeatureFilters {
  std::vector<float> gaussian, edge, point;
};
FeatureFilters featureFilters(float pixelsPerDegree) {
  const double sigma = 0.5 * kFeatureWidthDegrees * pixelsPerDegree;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> g, edge, point;
  for (int i = -radius; i <= radius; ++i) {
    const double x = i, gx = std::exp(-x * x / (2.0 * sigma * sigma));
    g.push_back(gx);
    edge.push_back(-x * gx);
    point.push_back((x * x / (sigma * sigma) - 1.0) * gx);
  }
  const auto normalised = [](const std::vector<double>& taps, bool signedParts) {
    double positive = 0.0, negative = 0.0;
    for (double t : taps) (t > 0.0 ? positive : negative) += t;
    std::vector<float> out;
    for (double t : taps)
      out.push_back(
          static_cast<float>(signedParts ? (t > 0.0 ? t / positive : t / -negative) : t / positive));
    return out;
  };
  return {normalised(g, false), normalised(edge, true), normalised(point, true)};
}

// Magnitudes of the edge and point responses of one luminance plane.
struct Features {
  Plane edge, point;
};
Features detectFeatures(const Plane& luminance, const FeatureFilters& filters) {
  const Plane edgeX = convolveSeparable(luminance, filters.edge, filters.gaussian);
  const Plane edgeY = convolveSeparable(luminance, filters.gaussian, filters.edge);
  const Plane pointX = convolveSeparable(luminance, filters.point, filters.gaussian);
  const Plane pointY = convolveSeparable(luminance, filters.gaussian, filters.point);
  Features features{Plane(luminance.width, luminance.height), Plane(luminance.width, luminance.height)};
  for (std::size_t i = 0; i < luminance.values.size(); ++i) {
    features.edge[i] = std::hypot(edgeX[i], edgeY[i]);
    features.point[i] = std::hypot(pointX[i], pointY[i]);
  }
  return features;
}

// One image in YCxCz, three planes, and its normalised luminance Y / Y_white for the feature
// detectors.
struct Opponent {
  Plane channels[3];
  Plane luminance;
};
Opponent toOpponent(const Image& image) {
  const int w = image.width(), h = image.height();
  Opponent out{{Plane(w, h), Plane(w, h), Plane(w, h)}, Plane(w, h)};
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    const glm::vec3 rgb = glm::clamp(glm::vec3(image.pixels()[i]), 0.0f, 1.0f);
    const glm::vec3 ycxcz = xyzToYcxcz(linearRgbToXyz(rgb));
    for (int c = 0; c < 3; ++c) out.channels[c][i] = ycxcz[c];
    out.luminance[i] = (ycxcz.x + 16.0f) / 116.0f;
  }
  return out;
}

// Filtered YCxCz back to linear RGB, clamped to [0,1] (the filters can leave the gamut), then to
// Hunt-adjusted L*a*b*.
glm::vec3 perceivedColor(const std::array<Plane, 3>& filtered, std::size_t i) {
  const glm::vec3 rgb =
      glm::clamp(xyzToLinearRgb(ycxczToXyz({filtered[0][i], filtered[1][i], filtered[2][i]})), 0.0f, 1.0f);
  return huntAdjust(xyzToLab(linearRgbToXyz(rgb)));
}

}  // namespace

FlipErrorMap ldrFlip(const Image& reference, const Image& test, float pixelsPerDegree) {
  if (reference.width() != test.width() || reference.height() != test.height())
    throw Error("ldrFlip: images of different sizes");
  const Opponent ref = toOpponent(reference), tst = toOpponent(test);
  const auto filtered = [pixelsPerDegree](const Opponent& image) {
    return std::array<Plane, 3>{filterWithCsf(image.channels[0], kCsf[0], pixelsPerDegree),
                                filterWithCsf(image.channels[1], kCsf[1], pixelsPerDegree),
                                filterWithCsf(image.channels[2], kCsf[2], pixelsPerDegree)};
  };
  const std::array<Plane, 3> refFiltered = filtered(ref), testFiltered = filtered(tst);
  const FeatureFilters filters = featureFilters(pixelsPerDegree);
  const Features refFeatures = detectFeatures(ref.luminance, filters);
  const Features testFeatures = detectFeatures(tst.luminance, filters);

  // The largest colour difference in the gamut, between Hunt-adjusted green and blue (colour pipeline).
  const float cmax = std::pow(hyab(huntAdjust(xyzToLab(linearRgbToXyz({0.0f, 1.0f, 0.0f}))),
                                   huntAdjust(xyzToLab(linearRgbToXyz({0.0f, 0.0f, 1.0f})))),
                              kColorExponent);
  const float knee = kKneeFraction * cmax;

  FlipErrorMap map{reference.width(), reference.height(), std::vector<float>(reference.pixelCount())};
  for (std::size_t i = 0; i < map.error.size(); ++i) {
    const float difference =
        std::pow(hyab(perceivedColor(refFiltered, i), perceivedColor(testFiltered, i)), kColorExponent);
    const float colorError = difference < knee
                                 ? kKneeError / knee * difference
                                 : kKneeError + (difference - knee) / (cmax - knee) * (1.0f - kKneeError);
    // Feature difference: the larger of the edge and point differences; 1/sqrt(2) maps the
    // largest possible response magnitude (sqrt 2, a unit step in x and y) to 1.
    const float featureDifference = std::max(std::abs(refFeatures.edge[i] - testFeatures.edge[i]),
                                             std::abs(refFeatures.point[i] - testFeatures.point[i]));
    const float featureError =
        std::pow(std::min(featureDifference / std::numbers::sqrt2_v<float>, 1.0f), kFeatureExponent);
    // Features amplify the colour error : errors on edges and points stand out.
    map.error[i] = std::pow(colorError, 1.0f - featureError);
  }
  return map;
}

namespace {
// RTG2 ch. 19's ACES tone mapper: Narkowicz's fit (a = 2.51, b = 0.03, c = 2.43, d = 0.59,
// e = 0.14) of 0.6 x.
constexpr double kAcesA = 2.51, kAcesB = 0.03, kAcesC = 2.43, kAcesD = 0.59, kAcesE = 0.14,
                 kAcesPrescale = 0.6;
}  // namespace

// The rational function is applied as written to every finite x and clamped to [0,1], as NVIDIA's
// implementation does: a radiance below about -0.02 comes out bright, so a negative value counts as
// an error instead of disappearing (docs/scoring.md).
float flipAces(float x) {
  if (std::isnan(x)) return 0.0f;
  const double v = kAcesPrescale * double(std::clamp(x, -1e30f, 1e30f));
  return static_cast<float>(
      std::clamp((v * (kAcesA * v + kAcesB)) / (v * (kAcesC * v + kAcesD) + kAcesE), 0.0, 1.0));
}

ExposureRange automaticExposureRange(const Image& reference) {
  // x where the tone mapper reaches 0.85: the positive root of (a - t c) v^2 + (b - t d) v - t e = 0
  // with v = 0.6 x.
  constexpr double kTarget = 0.85;
  const double qa = kAcesA - kTarget * kAcesC, qb = kAcesB - kTarget * kAcesD, qc = -kTarget * kAcesE;
  const double bright = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa) / kAcesPrescale;
  std::vector<float> luminances;
  luminances.reserve(reference.pixelCount());
  for (const glm::vec4& pixel : reference.pixels()) luminances.push_back(linearRgbToXyz(glm::vec3(pixel)).y);
  if (luminances.empty()) throw Error("automaticExposureRange: empty image");
  const auto middle = luminances.begin() + static_cast<std::ptrdiff_t>(luminances.size() / 2);
  std::nth_element(luminances.begin(), middle, luminances.end());
  const double median = *middle, maximum = *std::max_element(luminances.begin(), luminances.end());
  // The bracket starts where the brightest pixel reaches 0.85 and stops where the median pixel does.
  // A black (or negative) median or maximum has no such exposure: fall back to a one-stop bracket.
  const float start = maximum > 0.0 ? static_cast<float>(std::log2(bright / maximum)) : 0.0f;
  const float stop = median > 0.0 ? static_cast<float>(std::log2(bright / median)) : start + 1.0f;
  return exposureBracket(start, std::max(stop, start));
}

ExposureRange exposureBracket(float start, float stop) {
  return {start, stop, std::max(2, static_cast<int>(std::ceil(stop - start)))};
}

FlipErrorMap hdrFlip(const Image& reference, const Image& test, const ExposureRange& exposures,
                     float pixelsPerDegree) {
  FlipErrorMap result{reference.width(), reference.height(),
                      std::vector<float>(reference.pixelCount(), 0.0f)};
  const auto exposed = [](const Image& image, float scale) {
    Image out(image.width(), image.height());
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
      const glm::vec4& p = image.pixels()[i];
      out.pixels()[i] = glm::vec4(flipAces(p.r * scale), flipAces(p.g * scale), flipAces(p.b * scale), p.a);
    }
    return out;
  };
  // The exposures in parallel (a report scores a few hundred frames of 2-14 exposures each), each
  // thread keeping the maximum over its own; the maximum is exact in any order, so the map is the
  // same bit for bit on any number of threads. An exposure in flight holds about 120 bytes per
  // pixel (the exposed pair, the opponent, filtered and feature planes: 430 MB more peak memory for
  // a second one at 2560 x 1440), so no more run at once than fit in kFlipParallelBytes, and at
  // least one: a pair of 5K images or larger is scored one exposure at a time, as before.
  constexpr double kBytesPerPixel = 128.0, kFlipParallelBytes = 2.0 * 1024 * 1024 * 1024;
  const double perExposure = kBytesPerPixel * double(std::max<std::size_t>(reference.pixelCount(), 1));
  const int concurrency = std::clamp(int(std::min(kFlipParallelBytes / perExposure, 1024.0)), 1,
                                     tbb::this_task_arena::max_concurrency());
  tbb::combinable<std::vector<float>> maxima(
      [&] { return std::vector<float>(reference.pixelCount(), 0.0f); });
  tbb::task_arena(concurrency).execute([&] {
    tbb::parallel_for(0, exposures.count, [&](int e) {
      const float exposure = exposures.count == 1 ? exposures.start
                                                  : exposures.start + (exposures.stop - exposures.start) * e /
                                                                          float(exposures.count - 1);
      const float scale = std::exp2(exposure);
      const FlipErrorMap ldr = ldrFlip(exposed(reference, scale), exposed(test, scale), pixelsPerDegree);
      std::vector<float>& maximum = maxima.local();
      for (std::size_t i = 0; i < ldr.error.size(); ++i) maximum[i] = std::max(maximum[i], ldr.error[i]);
    });
  });
  maxima.combine_each([&](const std::vector<float>& maximum) {
    for (std::size_t i = 0; i < maximum.size(); ++i) result.error[i] = std::max(result.error[i], maximum[i]);
  });
  return result;
}

}  // namespace iblkit
