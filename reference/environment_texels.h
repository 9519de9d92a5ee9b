#pragma once
// The texels of a lat-long environment as the reference's light samplers draw them
// (environment_sampler.h, median_cut_sampler.h, oriented_environment.h): each texel's sampling
// weight, the point inside a texel, and the direction at that point with its density per steradian.
// The samplers pick a texel, and a point of [0,1]^2 inside it, from a piecewise-constant
// distribution over these weights; this is what turns that point into a direction.
//
// Weights, two kinds. meanWeights (what the samplers use): the mean over the texel of the bilinear
// luminance the lookups return, times the texel's solid angle; the point inside the texel is then
// drawn by that bilinear luminance itself (sampleWithin), so texel and point together follow the
// lookup's radiance, and next to a sun a texel's samples go where its light is. The luminance over
// a texel is four bilinear quarters through the values at its centre (the texel), its edge
// midpoints (the mean of it and a neighbour) and its corners (the mean of four): exact for the
// lookup in (u, v), and as a function of the point (across, down the solid angle) exact at those
// nine nodes. weights: the maximum of that bilinear luminance over the texel, with a uniform point;
// optionally with MIS compensation (Karlik et al. 2019; pbrt-v4's ImageInfiniteLight, Mitsuba 3's
// `mis_compensation`): the mean weight subtracted, keeping a floor of 0.1% of the mean, skipped
// for near-constant maps (max - min <= 1% of the mean). Both are non-zero wherever a lookup inside
// the texel can return radiance (the texel's 3x3 neighbourhood is not black).
//
// What this bought (docs/benchmarks.md, "Variance per sample"): the earlier weights, the 3x3
// maximum with a uniform point, spread a one-texel sun's weight over nine texels whose lookups
// mostly return a fraction of it; the bunny under sky had 4x the relMSE per sample.
//
// Directions: within a texel the fraction of the way down its row is linear in cos(theta), not
// theta, so a uniform point has a density per steradian exactly constant on the texel:
//   pdf(w) = pdf_uv(texel) / (2 pi H (cos theta_top - cos theta_bottom)),
// and sampleWithin's point that times its density relative to uniform.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "core/environment_map.h"

namespace iblkit {

class EnvironmentTexels {
 public:
  // Keeps a reference to `map`, which must outlive this.
  explicit EnvironmentTexels(const EnvironmentMap& map);

  const EnvironmentMap& map() const { return map_; }

  // The weights of the texels, row by row (row 0 first), proportional to the maximum bilinear
  // luminance over the texel x solid angle; MIS-compensated when asked and the map is not
  // near-constant (*compensated says whether it was).
  std::vector<float> weights(bool misCompensation, bool* compensated) const;
  // The same with each texel's mean bilinear luminance instead of its maximum: the weights that
  // sampleWithin's density completes, so that texel and point together are drawn proportionally
  // to the bilinear luminance (never MIS-compensated).
  std::vector<float> meanWeights() const;
  // What the samplers draw texels by: meanWeights, unless MIS compensation is asked for and the map
  // is not near-constant, in which case the compensated weights (and *compensated is true). The
  // point inside a texel is then to follow its bilinear luminance exactly when !*compensated.
  std::vector<float> samplingWeights(bool misCompensation, bool* compensated) const;

  // Inside a texel: a point of [0,1]^2 (across its columns, down its solid angle, as pointInRow
  // takes them) drawn from u proportionally to the bilinear luminance the lookups return there, as
  // a bilinear function of the point (exact at the texel's centre, edges and corners, which
  // split it into four bilinear quarters), and its density relative to the uniform point. The
  // density's mean over the texel is 1. A texel whose nine nodes lie within kFlatRatio of each
  // other (most of a sky, away from a sun) gives the uniform point with density 1, which costs it
  // under 1% more variance and saves the warp; so does a black texel.
  struct WithinTexel {
    glm::vec2 point{0.5f};
    float density = 1.0f;
  };
  WithinTexel sampleWithin(glm::ivec2 texel, glm::vec2 u) const;
  float densityWithin(glm::ivec2 texel, glm::vec2 point) const;
  // Where in its texel the direction of lat-long coordinates uv lies, in sampleWithin's terms.
  glm::vec2 pointWithin(glm::vec2 uv, glm::ivec2 texel) const;
  // densityWithin at the point of lat-long coordinates uv in `texel` (which holds it).
  float densityAtUv(glm::ivec2 texel, glm::vec2 uv) const {
    return shaped(texel) ? densityWithin(texel, pointWithin(uv, texel)) : 1.0f;
  }
  static constexpr float kFlatRatio = 1.2f;

  struct Point {
    glm::vec3 direction{0.0f};  // world direction, unit length
    glm::vec3 radiance{0.0f};   // the map's bilinear radiance there, intensity applied
  };
  // The point at longitude fraction u in [0,1] (u = 0.5 is the map's +Z) in texel row `row`, a
  // fraction `along` in [0,1] of the way down the row's solid angle.
  Point pointInRow(float u, int row, float along) const;

  // Density per steradian of a direction in texel row `row` whose density in (u, v) is pdfUv.
  float solidAnglePdf(float pdfUv, int row) const {
    return pdfUv * rowPdfScale_[static_cast<std::size_t>(row)];
  }

  struct Location {
    glm::vec2 uv{0.0f};        // lat-long coordinates in [0,1]^2
    glm::ivec2 texel{0};       // the texel uv lies in (column, row), clamped to the map
    glm::vec3 radiance{0.0f};  // the map's bilinear radiance, intensity applied
  };
  // Where world direction w (any non-zero length) lies in the map, and its radiance.
  Location locate(const glm::vec3& worldDirection) const { return locateUv(mapUv(worldDirection)); }
  // The lat-long coordinates of world direction w (any non-zero length): locate(w).uv.
  glm::vec2 mapUv(const glm::vec3& worldDirection) const;
  // locate(w) for uv = mapUv(w).
  Location locateUv(glm::vec2 uv) const;
  // The texel uv lies in (column, row), clamped to the map.
  glm::ivec2 texelAt(glm::vec2 uv) const;

  // Software prefetch of the texels a bilinear lookup around texel (column, row) reads (the texel
  // and its neighbours above and below; the columns beside it mostly share their cache lines), for
  // a batch of lookups whose cache misses should overlap. Reads nothing.
  void prefetchAround(glm::ivec2 texel) const;

 private:
  // The 3 x 3 node values of a texel's bilinear luminance (rows top edge, centre, bottom edge;
  // columns left edge, centre, right edge) and their mean over the texel.
  struct Nodes {
    float v[3][3];
    float mean;
    float lowest() const;
    float highest() const;
  };
  Nodes nodes(glm::ivec2 texel) const;
  static float densityAt(const Nodes& n, glm::vec2 point);  // n.mean > 0
  // Per texel, row by row: `luminance` of its nodes times its solid angle (proportional to its
  // row's cos(theta) span, times height / 2, which keeps the weights near sin(theta) x luminance).
  std::vector<float> nodeWeights(float (*luminance)(const Nodes&)) const;
  bool shaped(glm::ivec2 texel) const {
    return shaped_[static_cast<std::size_t>(texel.y) * static_cast<std::size_t>(map_.width()) +
                   static_cast<std::size_t>(texel.x)] != 0;
  }

  const EnvironmentMap& map_;
  std::vector<float> luminance_;    // per texel, row by row
  std::vector<std::uint8_t> shaped_;  // per texel: 1 where sampleWithin warps the point (not flat, not black)
  std::vector<float> rowCosTheta_;  // height + 1 row edges: cos of the polar angle from +Y, 1 to -1
  std::vector<float> rowPdfScale_;  // per row: 1 / (2 pi H (rowCosTheta_[y] - rowCosTheta_[y + 1]))
};

}  // namespace iblkit
