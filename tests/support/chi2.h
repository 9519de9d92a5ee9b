#pragma once
// Chi-square goodness-of-fit test of a sampler against the pdf it claims, in the style of
// Mitsuba 3's chi2.py (ChiSquareTest with SphericalDomain / planar domains) and pbrt's chi2 tests.
//
// The sampler is called sampleCount times; its points are binned on a grid over a 2D domain:
//   - the unit sphere, binned in (phi, cos theta) (equal-area bins) or in (phi, theta);
//   - the unit square [0,1]^2.
// Each bin's expected count is sampleCount times the pdf integrated over the bin (nested adaptive
// Simpson quadrature, starting from integrationPanels^2 sub-panels and refining where the estimate
// changes). A step of the pdf (an edge of its support, a cell of a tabulated pdf) that cuts off
// less than about 1/(2 integrationPanels) of a bin can go unseen: raise integrationPanels, or
// choose table sizes whose cell edges stay away from the bin edges. Bins expecting fewer than 5
// samples are pooled into one category, then Pearson's statistic gives a p-value for
// (categories - 1) degrees of freedom.
// The significance is Sidak-corrected for the number of tests in the suite:
// 1 - (1 - significance)^(1 / testCount).
//
// A sampler may decline (return nothing: an absorbed or rejected sample); such calls still count
// in sampleCount, so a pdf that integrates to less than 1 (the probability of producing a sample)
// is tested correctly.
//
// The test fails, with the reason in the message, when
//   - the p-value is below the corrected significance;
//   - more than 1e-5 sampleCount samples land in bins where the integrated pdf is 0, or at points
//     where the pdf is 0 (or not finite);
//   - the pdf integrates to something other than the fraction of calls that produced a sample
//     (|difference| > 1e-3 plus five binomial standard deviations);
//   - the sampler returns a non-finite point or a direction that is not unit length, or the pdf is
//     negative or not finite somewhere.
//
// Debugging: with IBLKIT_CHI2_DUMP=<folder> set, each test writes <name>.observed.tsv and
// <name>.expected.tsv there (one line per bin row, tab-separated counts).

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "core/rng.h"

namespace iblkit::test {

enum class SphereBinning {
  CosTheta,  // x = phi in [-pi, pi], y = cos(theta) in [-1, 1]: equal solid angle per bin
  Theta,     // x = phi in [-pi, pi], y = theta in [0, pi]: finer near the poles (peaked lobes)
};

struct Chi2Options {
  std::string name = "chi2";  // names the test in the message and the dump files
  std::int64_t sampleCount = 1'000'000;
  // Odd bin counts: no bin edge falls on phi = 0, z = 0 or the middle of the square, where
  // samplers put points exactly on a pdf's support boundary.
  int xBins = 61, yBins = 31;
  double significance = 0.01;
  int testCount = 1;  // tests in the suite, for the Sidak correction
  std::uint64_t seed = 7;
  SphereBinning sphereBinning = SphereBinning::CosTheta;
  int integrationPanels = 4;  // initial Simpson panels per bin and axis
  int integrationDepth = 6;   // adaptive refinement levels below each panel
};

struct Chi2Result {
  bool passed = false;
  double statistic = 0.0;  // Pearson's chi-square statistic
  int dof = 0;             // degrees of freedom: categories after pooling - 1
  double pValue = 0.0;
  double pdfIntegral = 0.0;     // the pdf integrated over the whole domain
  double sampleFraction = 0.0;  // fraction of sampler calls that produced a point
  std::string message;          // one paragraph: verdict, numbers, reasons for failing
};

// Directions on the unit sphere; the pdf is per steradian.
using DirectionSampler = std::function<std::optional<glm::vec3>(PCG32& rng)>;
using DirectionPdf = std::function<double(const glm::vec3& w)>;
Chi2Result chi2TestSphere(const DirectionSampler& sampler, const DirectionPdf& pdf,
                          const Chi2Options& options);

// Points in [0,1]^2; the pdf is per unit area. Points outside the square fail the test.
using PlanarSampler = std::function<std::optional<glm::vec2>(PCG32& rng)>;
using PlanarPdf = std::function<double(const glm::vec2& p)>;
Chi2Result chi2TestSquare(const PlanarSampler& sampler, const PlanarPdf& pdf, const Chi2Options& options);

// P(X >= statistic) for X chi-square distributed with dof >= 1 degrees of freedom: the regularised
// upper incomplete gamma function Q(dof/2, statistic/2) (series for x < a + 1, Legendre's
// continued fraction otherwise).
double chiSquareUpperTail(double statistic, int dof);

}  // namespace iblkit::test
