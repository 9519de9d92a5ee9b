#include "core/distribution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"

namespace iblkit {

namespace {

// The largest float below 1: samples and inverses stay in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

std::string formatValue(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
  return text;
}

// Throws unless every value is finite and non-negative; `where(i)` names value i.
template <class Where>
void requireFiniteNonNegative(std::span<const float> f, const char* owner, const Where& where) {
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!std::isfinite(f[i]) || f[i] < 0.0f) {
      throw Error(std::string(owner) + ": " + where(i) + " is " + formatValue(f[i]) +
                  " (must be finite and non-negative)");
    }
  }
}

// The cell of [0,1] split into n cells that x (in [0,1]) lies in.
int cellOf(float x, int n) { return std::clamp(static_cast<int>(x * static_cast<float>(n)), 0, n - 1); }

}  // namespace

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> f) : f_(f.begin(), f.end()) {
  if (f.empty()) throw Error("PiecewiseConstant1D: no function values");
  requireFiniteNonNegative(f, "PiecewiseConstant1D",
                           [](std::size_t i) { return "value " + std::to_string(i); });
  const std::size_t n = f.size();
  // Accumulate in double so that long tables keep a monotone, accurate CDF.
  std::vector<double> sums(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) sums[i + 1] = sums[i] + f[i];
  const double total = sums[n];
  integral_ = static_cast<float>(total / static_cast<double>(n));
  cdf_.resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    // All-zero function: the uniform CDF (documented fallback).
    const double c = total > 0.0 ? sums[i] / total : static_cast<double>(i) / static_cast<double>(n);
    cdf_[i] = static_cast<float>(c);
  }
  cdf_[n] = 1.0f;
  // Guide table (Chen and Asau 1974, "On Generating Random Variates from an Empirical
  // Distribution"): guide_[k] is the last cell whose CDF start is <= k / n, so sample() searches
  // only the few cells between two guide entries instead of the whole CDF.
  // The thresholds k / n rise with k, so one sweep over the CDF finds each entry's upper bound (the
  // first CDF value above the threshold) where a binary search per entry took n log n steps: 2.5 s
  // of an 8192 x 4096 map's 4096 rows.
  guide_.resize(n + 1);
  std::size_t upper = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const float threshold = static_cast<float>(k) / static_cast<float>(n);
    while (upper <= n && cdf_[upper] <= threshold) ++upper;
    guide_[k] = static_cast<int>(upper) - 1;
  }
  guide_[n] = static_cast<int>(n);
}

int PiecewiseConstant1D::searchCell(float u) const {
  // The last cell whose CDF start is <= u: its CDF end is > u, so it has non-zero probability.
  // A short table (the oriented environment's rows of cells) is counted, not searched: the CDF
  // is non-decreasing with cdf_[0] = 0 <= u < 1 = cdf_[n], so the number of inner entries at or
  // below u is the cell upper_bound finds, and the count has no branch to mispredict (the compiler
  // vectorises it).
  const int n = size();
  if (n <= kCountedCells) {
    int count = 0;
    for (int i = 1; i < n; ++i) count += cdf_[static_cast<std::size_t>(i)] <= u;
    return count;
  }
  // Searched between the guide entries one cell below and two above u's (a margin for the
  // rounding of u * n): every CDF value before the first is <= u and the one after the last is
  // > u, so the result is that of a search over the whole CDF.
  const SearchRange range = searchRange(u);
  const auto upper = std::upper_bound(cdf_.begin() + range.first, cdf_.begin() + range.last, u);
  return std::clamp(static_cast<int>(upper - cdf_.begin()) - 1, 0, size() - 1);
}

PiecewiseConstant1D::SearchRange PiecewiseConstant1D::searchRange(float u) const {
  const int n = size(), g = cellOf(u, n);
  const int first = guide_[static_cast<std::size_t>(std::max(g - 1, 0))];
  const int last = std::min(guide_[static_cast<std::size_t>(std::min(g + 2, n))] + 2, n + 1);
  return {first, last};
}

PiecewiseConstant1D::Sample PiecewiseConstant1D::sample(float u) const {
  u = std::clamp(u, 0.0f, kOneMinusEpsilon);
  const int offset = searchCell(u);
  const float width = cdf_[offset + 1] - cdf_[offset];
  const float du = width > 0.0f ? std::min((u - cdf_[offset]) / width, kOneMinusEpsilon) : 0.0f;
  Sample s;
  s.offset = offset;
  s.x = std::min((static_cast<float>(offset) + du) / static_cast<float>(size()), kOneMinusEpsilon);
  s.pdf = integral_ > 0.0f ? f_[offset] / integral_ : 1.0f;
  return s;
}

float PiecewiseConstant1D::pdf(float x) const {
  if (!(x >= 0.0f && x <= 1.0f)) return 0.0f;
  return integral_ > 0.0f ? f_[cellOf(x, size())] / integral_ : 1.0f;
}

void PiecewiseConstant1D::prefetchValue(float x) const { __builtin_prefetch(&f_[static_cast<std::size_t>(cellOf(x, size()))]); }

float PiecewiseConstant1D::invert(float x) const {
  x = std::clamp(x, 0.0f, 1.0f);
  const int offset = cellOf(x, size());
  const float delta = x * static_cast<float>(size()) - static_cast<float>(offset);
  const float u = cdf_[offset] + delta * (cdf_[offset + 1] - cdf_[offset]);
  return std::clamp(u, 0.0f, kOneMinusEpsilon);
}

namespace {

std::vector<PiecewiseConstant1D> rowDistributions(std::span<const float> f, int width, int height) {
  if (width < 1 || height < 1) {
    throw Error("PiecewiseConstant2D: grid size " + std::to_string(width) + " x " + std::to_string(height) +
                " is empty");
  }
  const std::size_t w = static_cast<std::size_t>(width);
  if (f.size() != w * static_cast<std::size_t>(height)) {
    throw Error("PiecewiseConstant2D: " + std::to_string(f.size()) + " values for a " +
                std::to_string(width) + " x " + std::to_string(height) + " grid");
  }
  requireFiniteNonNegative(f, "PiecewiseConstant2D", [w](std::size_t i) {
    return "value at column " + std::to_string(i % w) + ", row " + std::to_string(i / w);
  });
  std::vector<PiecewiseConstant1D> rows;
  rows.reserve(static_cast<std::size_t>(height));
  for (std::size_t v = 0; v < static_cast<std::size_t>(height); ++v) rows.emplace_back(f.subspan(v * w, w));
  return rows;
}

std::vector<float> rowIntegrals(const std::vector<PiecewiseConstant1D>& rows) {
  std::vector<float> integrals;
  integrals.reserve(rows.size());
  for (const PiecewiseConstant1D& row : rows) integrals.push_back(row.integral());
  return integrals;
}

}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> f, int width, int height)
    : conditional_(rowDistributions(f, width, height)), marginal_(rowIntegrals(conditional_)) {}

PiecewiseConstant2D::Sample PiecewiseConstant2D::sample(glm::vec2 u) const {
  const PiecewiseConstant1D::Sample row = marginal_.sample(u.y);
  const PiecewiseConstant1D::Sample column = conditional_[static_cast<std::size_t>(row.offset)].sample(u.x);
  Sample s;
  s.p = {column.x, row.x};
  s.pdf = column.pdf * row.pdf;
  s.offset = {column.offset, row.offset};
  return s;
}

void PiecewiseConstant2D::prefetchPdf(glm::vec2 p) const {
  if (!(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f)) return;
  conditional_[static_cast<std::size_t>(cellOf(p.y, height()))].prefetchValue(p.x);
}

float PiecewiseConstant2D::pdf(glm::vec2 p) const {
  if (!(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f)) return 0.0f;
  // conditional * marginal = (f / rowIntegral) * (rowIntegral / integral) = f / integral.
  const int row = cellOf(p.y, height());
  return conditional_[static_cast<std::size_t>(row)].pdf(p.x) * marginal_.pdf(p.y);
}

glm::vec2 PiecewiseConstant2D::invert(glm::vec2 p) const {
  const int row = cellOf(std::clamp(p.y, 0.0f, 1.0f), height());
  return {conditional_[static_cast<std::size_t>(row)].invert(p.x), marginal_.invert(p.y)};
}

}  // namespace iblkit
