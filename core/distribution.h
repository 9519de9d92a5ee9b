#pragma once
// Piecewise-constant distributions on [0,1] and [0,1]^2, for importance sampling tabulated
// functions (the environment map's luminance * sin(theta)). After pbrt-v4's PiecewiseConstant1D
// and PiecewiseConstant2D (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed.,
// Appendix A.4-A.5): the density is proportional to the function, sampling inverts the
// piecewise-linear CDF, and invert() maps a point back to the u that samples it.
//
// Input: finite, non-negative values; anything else throws Error (callers repair their data
// first). A function that is zero everywhere samples uniformly (its pdf is 1), so an all-black
// environment still gives valid samples.

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace iblkit {

class PiecewiseConstant1D {
 public:
  // f[i] is the function on the cell [i/n, (i+1)/n) of [0,1], n = f.size() >= 1.
  explicit PiecewiseConstant1D(std::span<const float> f);

  struct Sample {
    float x = 0.0f;    // in [0, 1)
    float pdf = 0.0f;  // density at x, > 0 (zero cells are never sampled)
    int offset = 0;    // the cell x lies in
  };
  // Sample for u in [0, 1).
  Sample sample(float u) const;
  // Density at x: f(x) / integral (1 for the all-zero function), 0 outside [0, 1].
  float pdf(float x) const;
  // The u with sample(u).x == x, for x in [0, 1] (clamped). In a zero cell, where no u samples x,
  // it returns the CDF value at the cell's start.
  float invert(float x) const;


  int size() const { return static_cast<int>(f_.size()); }
  // The CDF at the cell boundaries: size() + 1 values from 0 to 1.
  std::span<const float> cdf() const { return cdf_; }
  // Integral of the function over [0, 1] (the mean of the values).
  float integral() const { return integral_; }
  // Software prefetch of what pdf(x) reads, for x in [0, 1].
  void prefetchValue(float x) const;

 private:
  struct SearchRange {
    int first = 0, last = 0;  // the CDF entries sample() searches, [first, last)
  };
  // Tables of at most this many cells are searched by counting (searchCell), longer ones through
  // the guide table.
  static constexpr int kCountedCells = 64;
  SearchRange searchRange(float u) const;  // u in [0, 1)
  int searchCell(float u) const;           // the cell sample(u) picks, u in [0, 1)

  std::vector<float> f_;
  std::vector<float> cdf_;  // size() + 1 entries, cdf_[0] = 0, cdf_.back() = 1
  std::vector<int> guide_;  // size() + 1 entries: where sample() starts searching (see there)
  float integral_ = 0.0f;
};

class PiecewiseConstant2D {
 public:
  // f holds width * height values row by row: f[v * width + u] is the function on the cell
  // [u/width, (u+1)/width) x [v/height, (v+1)/height) of [0,1]^2 (row 0 first, as image rows).
  PiecewiseConstant2D(std::span<const float> f, int width, int height);

  struct Sample {
    glm::vec2 p{0.0f};     // in [0, 1)^2
    float pdf = 0.0f;      // density per unit area at p
    glm::ivec2 offset{0};  // the cell (column, row)
  };
  // Samples the row from the marginal with u.y, then the column within it with u.x.
  Sample sample(glm::vec2 u) const;
  // Density at p: f(p) / integral (1 for the all-zero function), 0 outside [0,1]^2.
  float pdf(glm::vec2 p) const;
  // The u with sample(u).p == p, for p in [0,1]^2.
  glm::vec2 invert(glm::vec2 p) const;
  // Software prefetch of what pdf(p) reads.
  void prefetchPdf(glm::vec2 p) const;

  int width() const { return static_cast<int>(conditional_.front().size()); }
  int height() const { return marginal_.size(); }
  // Integral of the function over [0,1]^2 (the mean of the values).
  float integral() const { return marginal_.integral(); }

 private:
  std::vector<PiecewiseConstant1D> conditional_;  // one per row, over u
  PiecewiseConstant1D marginal_;                  // over rows v, from each row's integral
};

}  // namespace iblkit
