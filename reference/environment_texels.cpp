#include "reference/environment_texels.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <numbers>

#include "core/fast_atan2.h"
#include "core/latlong.h"

namespace iblkit {

namespace {
// cos(theta) at the top edge of each texel row of a map `height` texels high, and at the bottom of
// the last: y = cos(pi * row / height), 1 at the north pole (+Y) to -1 at the south pole.
std::vector<float> rowEdges(int height) {
  std::vector<float> edges(static_cast<std::size_t>(height) + 1);
  for (int y = 0; y <= height; ++y)
    edges[static_cast<std::size_t>(y)] = static_cast<float>(std::cos(std::numbers::pi * y / height));
  edges.front() = 1.0f;
  edges.back() = -1.0f;
  return edges;
}
// Floor of the compensated weights, relative to the mean (pbrt-v4).
constexpr float kCompensationFloor = 1e-3f;
// Maps whose weights vary by less than this fraction of their mean are not compensated (Mitsuba 3).
constexpr float kNearConstant = 1e-2f;
}  // namespace

EnvironmentTexels::EnvironmentTexels(const EnvironmentMap& map)
    : map_(map), rowCosTheta_(rowEdges(map.height())) {
  luminance_.resize(static_cast<std::size_t>(map.width()) * static_cast<std::size_t>(map.height()));
  // Rows in parallel here and in nodeWeights (a 16384 x 8192 map is 134 M texels); each row writes
  // only its own entries, so the tables are the same whatever the threads.
  tbb::parallel_for(0, map.height(), [&](int y) {
    for (int x = 0; x < map.width(); ++x)
      luminance_[static_cast<std::size_t>(y) * map.width() + x] = map.texelLuminance(x, y);
  });
  shaped_.assign(luminance_.size(), 0);
  tbb::parallel_for(0, map.height(), [&](int y) {
    for (int x = 0; x < map.width(); ++x) {
      const Nodes n = nodes({x, y});
      shaped_[static_cast<std::size_t>(y) * map.width() + x] = n.mean > 0.0f && n.highest() > kFlatRatio * n.lowest();
    }
  });
  const double height = map.height();
  rowPdfScale_.resize(static_cast<std::size_t>(map.height()));
  for (std::size_t y = 0; y < rowPdfScale_.size(); ++y) {
    const double span = static_cast<double>(rowCosTheta_[y]) - static_cast<double>(rowCosTheta_[y + 1]);
    rowPdfScale_[y] = static_cast<float>(1.0 / (2.0 * std::numbers::pi * height * span));
  }
}

std::vector<float> EnvironmentTexels::nodeWeights(float (*luminance)(const Nodes&)) const {
  const int width = map_.width(), height = map_.height();
  std::vector<float> weights(luminance_.size());
  tbb::parallel_for(0, height, [&](int y) {
    const float rowSolidAngle =
        (rowCosTheta_[static_cast<std::size_t>(y)] - rowCosTheta_[static_cast<std::size_t>(y) + 1]) * 0.5f *
        static_cast<float>(height);
    for (int x = 0; x < width; ++x) weights[static_cast<std::size_t>(y) * width + x] = luminance(nodes({x, y})) * rowSolidAngle;
  });
  return weights;
}

std::vector<float> EnvironmentTexels::meanWeights() const {
  return nodeWeights([](const Nodes& n) { return n.mean; });
}

std::vector<float> EnvironmentTexels::samplingWeights(bool misCompensation, bool* compensated) const {
  *compensated = false;
  if (misCompensation) {
    std::vector<float> maxima = weights(true, compensated);
    if (*compensated) return maxima;
  }
  return meanWeights();
}

float EnvironmentTexels::Nodes::lowest() const {
  float lo = v[0][0];
  for (const auto& row : v)
    for (const float value : row) lo = std::min(lo, value);
  return lo;
}

float EnvironmentTexels::Nodes::highest() const {
  float hi = v[0][0];
  for (const auto& row : v)
    for (const float value : row) hi = std::max(hi, value);
  return hi;
}

EnvironmentTexels::Nodes EnvironmentTexels::nodes(glm::ivec2 texel) const {
  const int width = map_.width(), height = map_.height();
  // Neighbours as sampleLatLongBilinear reads them: columns wrapped, rows clamped at the poles.
  const int left = texel.x == 0 ? width - 1 : texel.x - 1, right = texel.x + 1 == width ? 0 : texel.x + 1;
  const int up = std::max(texel.y - 1, 0), down = std::min(texel.y + 1, height - 1);
  const int xs[3] = {left, texel.x, right}, ys[3] = {up, texel.y, down};
  float l[3][3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) l[j][i] = luminance_[static_cast<std::size_t>(ys[j]) * width + xs[i]];
  Nodes n;
  for (int j = 0; j < 3; j += 2)
    for (int i = 0; i < 3; i += 2) n.v[j][i] = 0.25f * (l[1][1] + l[1][i] + l[j][1] + l[j][i]);
  for (int j = 0; j < 3; j += 2) n.v[j][1] = 0.5f * (l[1][1] + l[j][1]);
  for (int i = 0; i < 3; i += 2) n.v[1][i] = 0.5f * (l[1][1] + l[1][i]);
  n.v[1][1] = l[1][1];
  // Each quarter's mean is the mean of its four corners; the texel's the mean of the quarters'.
  float sum = 0.0f;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) sum += n.v[j][i] + n.v[j][i + 1] + n.v[j + 1][i] + n.v[j + 1][i + 1];
  n.mean = sum / 16.0f;
  return n;
}

namespace {
// The largest float below 1.
constexpr float kBelowOne = 0x1.fffffep-1f;
// A point of [0, 1] drawn from u with density proportional to the line from a (at 0) to b (at 1)
// (pbrt-v4's SampleLinear).
float sampleLinear(float u, float a, float b) {
  if (u == 0.0f && a == 0.0f) return 0.0f;
  const float x = u * (a + b) / (a + std::sqrt(std::max(0.0f, glm::mix(a * a, b * b, u))));
  return std::min(x, kBelowOne);
}
// A point of [0, 1] drawn from u proportionally to the piecewise-linear function with values
// n0, n1, n2 at 0, 1/2 and 1.
float sampleTwoSegments(float u, float n0, float n1, float n2) {
  const float first = n0 + n1, second = n1 + n2;
  if (first + second <= 0.0f) return u;
  const float split = first / (first + second);
  if (u < split) return 0.5f * sampleLinear(std::min(u / split, kBelowOne), n0, n1);
  return 0.5f + 0.5f * sampleLinear(std::min((u - split) / (1.0f - split), kBelowOne), n1, n2);
}
}  // namespace

EnvironmentTexels::WithinTexel EnvironmentTexels::sampleWithin(glm::ivec2 texel, glm::vec2 u) const {
  if (!shaped(texel)) return {u, 1.0f};
  const Nodes n = nodes(texel);
  // Down the texel: the marginal, piecewise linear through the rows' means (trapezoids).
  float rows[3];
  for (int j = 0; j < 3; ++j) rows[j] = n.v[j][0] + 2.0f * n.v[j][1] + n.v[j][2];
  WithinTexel out;
  out.point.y = sampleTwoSegments(u.y, rows[0], rows[1], rows[2]);
  // Across it, at that height: the nodes interpolated between the two rows around it.
  const int j = out.point.y < 0.5f ? 0 : 1;
  const float t = 2.0f * out.point.y - static_cast<float>(j);
  float across[3];
  for (int i = 0; i < 3; ++i) across[i] = glm::mix(n.v[j][i], n.v[j + 1][i], t);
  out.point.x = sampleTwoSegments(u.x, across[0], across[1], across[2]);
  out.density = densityAt(n, out.point);
  return out;
}

float EnvironmentTexels::densityWithin(glm::ivec2 texel, glm::vec2 point) const {
  if (!shaped(texel)) return 1.0f;
  return densityAt(nodes(texel), point);
}

float EnvironmentTexels::densityAt(const Nodes& n, glm::vec2 point) {
  const float sx = std::clamp(point.x, 0.0f, 1.0f) * 2.0f, sy = std::clamp(point.y, 0.0f, 1.0f) * 2.0f;
  const int i = std::min(static_cast<int>(sx), 1), j = std::min(static_cast<int>(sy), 1);
  const float fx = sx - static_cast<float>(i), fy = sy - static_cast<float>(j);
  const float top = glm::mix(n.v[j][i], n.v[j][i + 1], fx), bottom = glm::mix(n.v[j + 1][i], n.v[j + 1][i + 1], fx);
  return glm::mix(top, bottom, fy) / n.mean;
}

glm::vec2 EnvironmentTexels::pointWithin(glm::vec2 uv, glm::ivec2 texel) const {
  const std::size_t y = static_cast<std::size_t>(texel.y);
  const float cosTheta = std::cos(glm::pi<float>() * std::clamp(uv.y, 0.0f, 1.0f));
  const float span = rowCosTheta_[y] - rowCosTheta_[y + 1];
  return {std::clamp(uv.x * static_cast<float>(map_.width()) - static_cast<float>(texel.x), 0.0f, 1.0f),
          std::clamp((rowCosTheta_[y] - cosTheta) / span, 0.0f, 1.0f)};
}

std::vector<float> EnvironmentTexels::weights(bool misCompensation, bool* compensated) const {
  // The maximum over the texel of the bilinear luminance the lookups return: the largest of its
  // nine node values (a bilinear quarter peaks at a corner).
  std::vector<float> weights = nodeWeights([](const Nodes& n) { return n.highest(); });
  *compensated = false;
  if (misCompensation) {
    double sum = 0.0;
    float lo = weights.front(), hi = weights.front();
    for (const float w : weights) {
      sum += w;
      lo = std::min(lo, w);
      hi = std::max(hi, w);
    }
    const float mean = static_cast<float>(sum / static_cast<double>(weights.size()));
    if (mean > 0.0f && hi - lo > kNearConstant * mean) {
      for (float& w : weights) w = std::max(w - mean, std::min(kCompensationFloor * mean, w));
      *compensated = true;
    }
  }
  return weights;
}

EnvironmentTexels::Point EnvironmentTexels::pointInRow(float u, int row, float along) const {
  const std::size_t y = static_cast<std::size_t>(row);
  const float cosTheta = std::clamp(glm::mix(rowCosTheta_[y], rowCosTheta_[y + 1], along), -1.0f, 1.0f);
  const float sinTheta = std::sqrt(std::max(0.0f, (1.0f - cosTheta) * (1.0f + cosTheta)));
  const float longitude = 2.0f * glm::pi<float>() * (0.5f - u);
  const glm::vec3 mapDirection(sinTheta * std::sin(longitude), cosTheta, sinTheta * std::cos(longitude));
  const glm::vec2 uv(u, fastAtan2(sinTheta, cosTheta) / glm::pi<float>());  // theta / pi
  Point out;
  out.direction = map_.toWorldDirection(mapDirection);
  // The bilinear lookup at (u, v) itself: map_.radiance(out.direction) would find the same point
  // again through two arctangents.
  out.radiance = map_.intensity() * sampleLatLongBilinear(map_.image(), uv);
  return out;
}

glm::vec2 EnvironmentTexels::mapUv(const glm::vec3& worldDirection) const {
  return latLongUv(glm::normalize(map_.toMapDirection(worldDirection)));
}

glm::ivec2 EnvironmentTexels::texelAt(glm::vec2 uv) const {
  return glm::ivec2(std::clamp(static_cast<int>(uv.x * static_cast<float>(map_.width())), 0, map_.width() - 1),
                    std::clamp(static_cast<int>(uv.y * static_cast<float>(map_.height())), 0, map_.height() - 1));
}

EnvironmentTexels::Location EnvironmentTexels::locateUv(glm::vec2 uv) const {
  Location out;
  out.uv = uv;
  out.radiance = map_.intensity() * sampleLatLongBilinear(map_.image(), out.uv);
  out.texel = texelAt(uv);
  return out;
}

void EnvironmentTexels::prefetchAround(glm::ivec2 texel) const {
  const Image& image = map_.image();
  const int x = std::clamp(texel.x, 0, image.width() - 1), y = std::clamp(texel.y, 0, image.height() - 1);
  __builtin_prefetch(&image.at(x, y));
  __builtin_prefetch(&image.at(x, std::max(y - 1, 0)));
  __builtin_prefetch(&image.at(x, std::min(y + 1, image.height() - 1)));
}

}  // namespace iblkit
