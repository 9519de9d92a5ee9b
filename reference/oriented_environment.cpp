#include "reference/oriented_environment.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace iblkit {

namespace {

// The largest float below 1: a rescaled u stays in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
// Angle margin for float rounding in the cells' geometry.
constexpr float kMarginRadians = 1e-3f;

// The map-space direction at longitude fraction u (0.5 is +Z) and polar angle theta from +Y, as
// EnvironmentTexels::pointInRow has it.
glm::vec3 mapDirection(double u, double theta) {
  const double longitude = 2.0 * glm::pi<double>() * (0.5 - u);
  return glm::vec3(glm::dvec3(std::sin(theta) * std::sin(longitude), std::cos(theta),
                              std::sin(theta) * std::cos(longitude)));
}

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

// `count` cells over `size` texels: the texel edges, as even as integers allow.
std::vector<int> edges(int size, int count) {
  std::vector<int> out(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i)
    out[static_cast<std::size_t>(i)] = static_cast<int>(static_cast<long long>(i) * size / count);
  return out;
}

std::vector<int> cellOfTexel(const std::vector<int>& edge, int size) {
  std::vector<int> out(static_cast<std::size_t>(size));
  for (std::size_t c = 0; c + 1 < edge.size(); ++c)
    for (int t = edge[c]; t < edge[c + 1]; ++t) out[static_cast<std::size_t>(t)] = static_cast<int>(c);
  return out;
}

}  // namespace

OrientedEnvironment::OrientedEnvironment(const EnvironmentTexels& texels, std::vector<float> weights)
    : texels_(texels),
      width_(texels.map().width()),
      height_(texels.map().height()),
      columns_(std::min(kCellColumns, width_)),
      rows_(std::min(kCellRows, height_)),
      columnStart_(edges(width_, columns_)),
      rowStart_(edges(height_, rows_)),
      columnCell_(cellOfTexel(columnStart_, width_)),
      rowCell_(cellOfTexel(rowStart_, height_)),
      weights_(std::move(weights)) {
  const std::size_t cellCount = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  cellWeight_.assign(cellCount, 0.0f);
  cellOffset_.assign(cellCount + 1, 0);
  cellRowOffset_.assign(cellCount + 1, 0);
  texelCdf_.assign(weights_.size(), 0.0f);
  // Each cell's texels in a block of their own, row by row: each row's CDF over its columns, and the
  // cell's CDF over its rows. And the cell's centre direction and radius (its corners are its
  // farthest points from the centre: along a meridian the angle to a point grows away from the
  // nearest point, along a parallel with the longitude).
  std::vector<glm::vec3> cellCentre(cellCount);
  std::vector<float> cellRadius(cellCount);
  int offset = 0;
  for (int cy = 0; cy < rows_; ++cy)
    for (int cx = 0; cx < columns_; ++cx) {
      const std::size_t cell = static_cast<std::size_t>(cy) * columns_ + cx;
      const int x0 = columnStart_[static_cast<std::size_t>(cx)], x1 = columnStart_[static_cast<std::size_t>(cx) + 1];
      const int y0 = rowStart_[static_cast<std::size_t>(cy)], y1 = rowStart_[static_cast<std::size_t>(cy) + 1];
      cellOffset_[cell] = offset;
      cellRowOffset_[cell] = static_cast<int>(rowCdf_.size());
      std::vector<double> rowSums;
      for (int y = y0; y < y1; ++y) {
        double rowSum = 0.0;
        for (int x = x0; x < x1; ++x) rowSum += weights_[static_cast<std::size_t>(y) * width_ + x];
        double running = 0.0;
        for (int x = x0; x < x1; ++x) {
          running += weights_[static_cast<std::size_t>(y) * width_ + x];
          texelCdf_[static_cast<std::size_t>(offset++)] = rowSum > 0.0 ? static_cast<float>(running / rowSum) : 0.0f;
        }
        if (rowSum > 0.0) texelCdf_[static_cast<std::size_t>(offset) - 1] = 1.0f;
        rowSums.push_back(rowSum);
      }
      double sum = 0.0;
      for (const double r : rowSums) sum += r;
      double running = 0.0;
      for (const double r : rowSums) {
        running += r;
        rowCdf_.push_back(sum > 0.0 ? static_cast<float>(running / sum) : 0.0f);
      }
      if (sum > 0.0) rowCdf_.back() = 1.0f;
      cellWeight_[cell] = static_cast<float>(sum);

      const double u0 = double(x0) / width_, u1 = double(x1) / width_;
      const double t0 = glm::pi<double>() * y0 / height_, t1 = glm::pi<double>() * y1 / height_;
      const glm::vec3 centre = mapDirection(0.5 * (u0 + u1), 0.5 * (t0 + t1));
      float radius = 0.0f;
      for (const double u : {u0, u1})
        for (const double t : {t0, t1}) radius = std::max(radius, angleBetween(centre, mapDirection(u, t)));
      cellCentre[cell] = centre;
      cellRadius[cell] = radius;
    }
  cellOffset_[cellCount] = offset;
  cellRowOffset_[cellCount] = static_cast<int>(rowCdf_.size());
  cellCentre_ = cellCentre;
  cellCosSinRadius_.resize(cellCount);
  for (std::size_t cell = 0; cell < cellCount; ++cell)
    cellCosSinRadius_[cell] = {std::cos(cellRadius[cell]), std::sin(cellRadius[cell])};

  bounds_.resize(cellCount * NormalBuckets::kCount);
  texelScale_.reserve(cellCount * NormalBuckets::kCount);
  cellDistribution_.reserve(NormalBuckets::kCount);
  std::vector<float> f(cellCount);
  const float halfPi = 0.5f * glm::pi<float>();
  for (int b = 0; b < NormalBuckets::kCount; ++b) {
    const glm::vec3 normal = glm::normalize(texels.map().toMapDirection(NormalBuckets::center(b)));
    const float cone = NormalBuckets::coneRadius(b) + kMarginRadians;
    float* bound = &bounds_[static_cast<std::size_t>(b) * cellCount];
    for (std::size_t cell = 0; cell < cellCount; ++cell) {
      const float gap = angleBetween(normal, cellCentre[cell]) - cone - cellRadius[cell];
      bound[cell] = gap <= 0.0f ? 1.0f : (gap >= halfPi ? 0.0f : std::cos(gap));
      f[cell] = cellWeight_[cell] * bound[cell];
    }
    cellDistribution_.emplace_back(f, columns_, rows_);
    const PiecewiseConstant2D& cells = cellDistribution_.back();
    for (int cy = 0; cy < rows_; ++cy)
      for (int cx = 0; cx < columns_; ++cx) {
        const std::size_t cell = static_cast<std::size_t>(cy) * columns_ + static_cast<std::size_t>(cx);
        const float cellProbability =
            cells.pdf({(static_cast<float>(cx) + 0.5f) / static_cast<float>(columns_),
                       (static_cast<float>(cy) + 0.5f) / static_cast<float>(rows_)}) /
            (static_cast<float>(columns_) * static_cast<float>(rows_));
        texelScale_.push_back(cells.integral() > 0.0f && cellWeight_[cell] > 0.0f
                                  ? cellProbability / cellWeight_[cell] * static_cast<float>(width_) *
                                        static_cast<float>(height_)
                                  : 0.0f);
      }
  }
}

float OrientedEnvironment::cosineBound(int bucket, glm::ivec2 cell) const {
  const std::size_t cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  return bounds_[static_cast<std::size_t>(bucket) * cells + static_cast<std::size_t>(cell.y) * columns_ +
                 static_cast<std::size_t>(cell.x)];
}

namespace {
// The entry of an inclusive CDF [first, last) (ending at 1) that u in [0, 1) falls in: the first that
// exceeds u (zero-weight entries never do), and u's fraction of the way through it.
struct Found {
  int index = 0;
  float fraction = 0.0f;
};
Found findInCdf(const float* first, const float* last, float u) {
  // A cell's rows and columns are few (8 on a 512 x 256 map): counting the entries at or below u
  // has no branch to mispredict, unlike a binary search.
  const std::ptrdiff_t size = last - first;
  const float* found;
  if (size <= 32) {
    std::ptrdiff_t count = 0;
    for (std::ptrdiff_t i = 0; i + 1 < size; ++i) count += first[i] <= u;
    found = first + count;
  } else {
    found = std::min(std::upper_bound(first, last, u), last - 1);
  }
  const float below = found == first ? 0.0f : found[-1];
  const float fraction = found[0] > below ? std::clamp((u - below) / (found[0] - below), 0.0f, kOneMinusEpsilon) : 0.5f;
  return {static_cast<int>(found - first), fraction};
}
}  // namespace

OrientedEnvironment::Pick OrientedEnvironment::sample(int bucket, glm::vec2 u, const DirectionCone* within) const {
  const PiecewiseConstant2D& cells = cellDistribution_[static_cast<std::size_t>(bucket)];
  Pick out;
  if (cells.integral() <= 0.0f) return out;  // no light this bucket's normals can receive
  const PiecewiseConstant2D::Sample picked = cells.sample(u);
  const int cx = picked.offset.x, cy = picked.offset.y;
  const std::size_t cell = static_cast<std::size_t>(cy) * columns_ + static_cast<std::size_t>(cx);
  if (within && within->cosRadius > -1.0f) {
    // Every point of the cell is within its radius r of the centre, so none is in the cone when the
    // centre is farther than the cone's half-angle a plus r from the axis: cos(angle) < cos(a + r)
    // (a + r < pi), with a margin for the rounding of the directions.
    const glm::vec2 r = cellCosSinRadius_[cell];
    const float cosSum = within->cosRadius * r.x - within->sinRadius * r.y;
    const bool below = within->cosRadius * r.y + within->sinRadius * r.x > 0.0f;  // sin(a + r) > 0: a + r < pi
    if (below && glm::dot(within->axis, cellCentre_[cell]) < cosSum - 1e-5f) return out;
  }
  // What is left of u inside the cell picks its row, then the row's column.
  const float acrossCell =
      std::clamp(picked.p.x * static_cast<float>(columns_) - static_cast<float>(cx), 0.0f, kOneMinusEpsilon);
  const float downCell = std::clamp(picked.p.y * static_cast<float>(rows_) - static_cast<float>(cy), 0.0f, kOneMinusEpsilon);
  const Found row = findInCdf(rowCdf_.data() + cellRowOffset_[cell], rowCdf_.data() + cellRowOffset_[cell + 1], downCell);
  const int x0 = columnStart_[static_cast<std::size_t>(cx)];
  const int cellWidth = columnStart_[static_cast<std::size_t>(cx) + 1] - x0;
  const float* rowFirst = texelCdf_.data() + cellOffset_[cell] + static_cast<std::ptrdiff_t>(row.index) * cellWidth;
  const Found column = findInCdf(rowFirst, rowFirst + cellWidth, acrossCell);
  out.texel = {x0 + column.index, rowStart_[static_cast<std::size_t>(cy)] + row.index};
  out.within = {column.fraction, row.fraction};
  // P(cell) P(texel | cell), over the texel's area 1 / (width height) in (u, v).
  out.pdfUv = weights_[static_cast<std::size_t>(out.texel.y) * width_ + out.texel.x] * texelScale(bucket, cell);
  return out;
}

float OrientedEnvironment::pdfUv(int bucket, glm::ivec2 texel) const {
  return weights_[static_cast<std::size_t>(texel.y) * width_ + texel.x] *
         texelScale(bucket, static_cast<std::size_t>(cellOf(texel)));
}

void OrientedEnvironment::prefetchPdf(int bucket, glm::ivec2 texel) const {
  __builtin_prefetch(&texelScale_[static_cast<std::size_t>(bucket) * static_cast<std::size_t>(columns_ * rows_) +
                                  static_cast<std::size_t>(cellOf(texel))]);
  __builtin_prefetch(&weights_[static_cast<std::size_t>(texel.y) * width_ + texel.x]);
}

}  // namespace iblkit
