#pragma once
// Environment importance sampling for the normal of the vertex being lit ("the environment sampler
// where the ground sees the sun", issue 16). The plain sampler (environment_sampler.h) draws texels
// by their weight alone, luminance x solid angle, so a ground plane under a photograph spends the
// samples that land below its horizon (10-16% of the bundled maps' energy) on nothing, and weighs a
// sun at the zenith like one at the horizon. Here each bucket of normals (normal_buckets.h) has its
// own distribution, the texel weights times a bound of the cosine that any normal of the bucket
// makes with any direction of a cell of texels:
//
//   p_b(texel t) = w_t c_b(cell(t)) / sum_t' w_t' c_b(cell(t')),
//   c_b(cell) = cos(max(0, angle(centre_b, centre_cell) - coneRadius_b - radius_cell)), 0 past 90 degrees.
//
// c_b is at least max(0, n . w) for every normal n of the bucket and every direction w of the cell
// (triangle inequality on the sphere), and it is zero only where n . w <= 0 for all of them: the
// density is positive wherever a vertex of the bucket can receive light, so next-event estimation
// with it stays unbiased (the integrator counts light only where n . w > 0), and within a texel it is
// uniform over the solid angle like the plain sampler's. For a normal on an axis (the ground) the
// bound is the cosine itself up to a cell's radius.
//
// Sampling is the plain sampler's 2D inversion, twice: a cell of a grid of at most kCellColumns x
// kCellRows blocks of texels by its weight sum_{t in cell} w_t c_b(cell) (a PiecewiseConstant2D over
// the cells per bucket: a row with u.y, then a column with u.x), then a texel of the cell by w_t
// from what is left of u (a row of the cell, then a column of that row, from tables shared by all
// buckets), then the point inside the texel from what is left after that. A stratified u stays
// stratified over the sphere, and the per-bucket tables do not grow with the map.

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/distribution.h"
#include "reference/environment_texels.h"
#include "reference/normal_buckets.h"

namespace iblkit {

class OrientedEnvironment {
 public:
  static constexpr int kCellColumns = 64, kCellRows = 32;

  // `weights`: the texels' sampling weights row by row (EnvironmentTexels::weights of `texels`' map).
  // Keeps a reference to `texels`, which must outlive this.
  // (Taken by value: the caller moves them in, and a large map's tables are not held twice.)
  OrientedEnvironment(const EnvironmentTexels& texels, std::vector<float> weights);

  struct Pick {
    glm::ivec2 texel{0};       // (column, row)
    glm::vec2 within{0.0f};    // the point inside the texel: across its columns, down its solid angle
    float pdfUv = 0.0f;        // density per unit area of (u, v); 0 when the bucket sees no light
  };
  // A cone of map directions: unit axis, cos and sin of the half-angle (in [0, pi]).
  struct DirectionCone {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    float cosRadius = -1.0f, sinRadius = 0.0f;
  };
  // A texel for a vertex whose normal is in `bucket`, from u in [0,1)^2. With `within`, a pick whose
  // cell lies wholly outside that cone stops at the cell and comes back empty (pdfUv 0): the same
  // draw as without it for every point that can be inside the cone (ground occlusion, whose light
  // samples outside the objects' cone count nothing, skips the texel-level work of the rest).
  Pick sample(int bucket, glm::vec2 u, const DirectionCone* within = nullptr) const;
  // The density per unit area of (u, v) that sample(bucket, .) has on `texel`.
  float pdfUv(int bucket, glm::ivec2 texel) const;
  // Software prefetch of what pdfUv reads. It changes nothing.
  void prefetchPdf(int bucket, glm::ivec2 texel) const;

  glm::ivec2 cells() const { return {columns_, rows_}; }
  // The texels' weights it was built from, row by row.
  std::span<const float> weights() const { return weights_; }
  // c_b of cell (column, row) of the grid (for the tests).
  float cosineBound(int bucket, glm::ivec2 cell) const;
  // The cell a texel lies in.
  int cellOf(glm::ivec2 texel) const {
    return rowCell_[static_cast<std::size_t>(texel.y)] * columns_ + columnCell_[static_cast<std::size_t>(texel.x)];
  }

 private:
  const EnvironmentTexels& texels_;
  int width_ = 0, height_ = 0, columns_ = 0, rows_ = 0;
  std::vector<int> columnStart_, rowStart_;  // columns_ + 1, rows_ + 1 texel edges of the cells
  std::vector<int> columnCell_, rowCell_;    // per texel column and row: its cell column and row
  std::vector<float> weights_;               // w_t, row by row
  std::vector<float> cellWeight_;            // sum of w_t over each cell
  std::vector<int> cellOffset_;              // where each cell's texels start in texelCdf_
  std::vector<int> cellRowOffset_;           // where each cell's rows start in rowCdf_
  std::vector<float> rowCdf_;                // per cell, over its rows: inclusive CDF of their sums, ending at 1
  std::vector<float> texelCdf_;              // per cell, per row of it: inclusive CDF over the row, ending at 1
  std::vector<PiecewiseConstant2D> cellDistribution_;  // per bucket, over the cells
  std::vector<float> bounds_;                          // per bucket, c_b of each cell
  // Per bucket and cell: P(cell) / (sum of w_t over the cell) x width x height, so that a texel's
  // density in (u, v) is its weight times this (one read where the distribution takes three).
  std::vector<float> texelScale_;
  // Per cell: its centre's map direction, and cos and sin of the angle from it to its farthest point.
  std::vector<glm::vec3> cellCentre_;
  std::vector<glm::vec2> cellCosSinRadius_;
  float texelScale(int bucket, std::size_t cell) const {
    return texelScale_[static_cast<std::size_t>(bucket) * static_cast<std::size_t>(columns_ * rows_) + cell];
  }
};

}  // namespace iblkit
