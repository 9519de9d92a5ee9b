#include "support/chi2.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <numeric>
#include <vector>

namespace iblkit::test {

namespace {

constexpr double kPi = glm::pi<double>();
constexpr double kMinExpected = 5.0;           // pooling threshold per category
constexpr double kStrayFraction = 1e-5;        // tolerated samples where the pdf is 0
constexpr double kIntegralTolerance = 1e-3;    // |pdf integral - sample fraction|
constexpr double kUnitLengthTolerance = 1e-3;  // directions must be unit vectors

// What one sampler call produced, mapped to the binned parameter space.
struct Draw {
  enum class Kind { Nothing, Point, Invalid } kind = Kind::Nothing;
  glm::dvec2 p{0.0};        // in the bin space
  double pdfAtPoint = 0.0;  // the pdf at the sample, in the sampler's measure
};

// A 2D domain as the test sees it: a rectangle in parameter space, a sampler mapped into it and
// the pdf times the Jacobian of the parameterisation (density per unit parameter area).
struct Domain {
  glm::dvec2 lo, hi;
  std::function<Draw(PCG32&)> draw;
  std::function<double(double, double)> density;
};

// Simpson's rule on [a, b] refined where the two halves disagree with the whole (Kuncir 1962;
// Lyness 1969), without Richardson's extrapolation term so that a non-negative integrand never
// gets a negative integral.
template <class F>
double simpsonRefine(const F& f, double a, double b, double fa, double fm, double fb, double whole,
                     double eps, int depth) {
  const double m = 0.5 * (a + b);
  const double flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * eps) return left + right;
  return simpsonRefine(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
         simpsonRefine(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

// Adaptive Simpson over `panels` equal panels of [a, b], each refined up to `depth` levels.
template <class F>
double adaptiveSimpson(const F& f, double a, double b, double eps, int panels, int depth) {
  const double h = (b - a) / panels;
  double sum = 0.0;
  double fa = f(a);
  for (int i = 0; i < panels; ++i) {
    const double x0 = a + i * h, x1 = i + 1 == panels ? b : a + (i + 1) * h;
    const double fm = f(0.5 * (x0 + x1)), fb = f(x1);
    const double whole = (x1 - x0) / 6.0 * (fa + 4.0 * fm + fb);
    sum += simpsonRefine(f, x0, x1, fa, fm, fb, whole, eps / panels, depth);
    fa = fb;
  }
  return sum;
}

std::string format(const char* pattern, double a) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, a);
  return text;
}

std::string fileSafe(const std::string& name) {
  std::string safe = name;
  for (char& c : safe) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  }
  return safe;
}

// Writes one grid of numbers, a line per row, to a temporary name and renames it into place.
void writeGrid(const std::filesystem::path& file, const std::vector<double>& values, int width) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary);
    for (std::size_t i = 0; i < values.size(); ++i) {
      out << values[i] << ((i + 1) % static_cast<std::size_t>(width) == 0 ? '\n' : '\t');
    }
  }
  std::filesystem::rename(temporary, file);
}

void dumpHistograms(const std::string& name, const std::vector<double>& observed,
                    const std::vector<double>& expected, int width) {
  const char* folder = std::getenv("IBLKIT_CHI2_DUMP");
  if (folder == nullptr || *folder == '\0') return;
  const std::filesystem::path dir(folder);
  std::filesystem::create_directories(dir);
  writeGrid(dir / (fileSafe(name) + ".observed.tsv"), observed, width);
  writeGrid(dir / (fileSafe(name) + ".expected.tsv"), expected, width);
}

Chi2Result runTest(const Domain& domain, const Chi2Options& options) {
  const int nx = options.xBins, ny = options.yBins;
  const double n = static_cast<double>(options.sampleCount);
  const glm::dvec2 extent = domain.hi - domain.lo;

  // Histogram of the samples.
  std::vector<double> observed(static_cast<std::size_t>(nx * ny), 0.0);
  std::int64_t produced = 0, invalid = 0, zeroPdf = 0;
  PCG32 rng(options.seed);
  for (std::int64_t i = 0; i < options.sampleCount; ++i) {
    const Draw d = domain.draw(rng);
    if (d.kind == Draw::Kind::Nothing) continue;
    if (d.kind == Draw::Kind::Invalid) {
      ++invalid;
      continue;
    }
    ++produced;
    if (!(d.pdfAtPoint > 0.0) || !std::isfinite(d.pdfAtPoint)) ++zeroPdf;
    const glm::dvec2 t = (d.p - domain.lo) / extent;
    const int ix = std::clamp(static_cast<int>(t.x * nx), 0, nx - 1);
    const int iy = std::clamp(static_cast<int>(t.y * ny), 0, ny - 1);
    observed[static_cast<std::size_t>(iy * nx + ix)] += 1.0;
  }

  // Expected counts: the pdf integrated over each bin.
  bool badDensity = false;
  const auto density = [&](double x, double y) {
    const double v = domain.density(x, y);
    if (!std::isfinite(v) || v < 0.0) {
      badDensity = true;
      return 0.0;
    }
    return v;
  };
  const double binWidth = extent.x / nx, binHeight = extent.y / ny;
  const double eps = 1e-3 / n;  // absolute error per bin, in probability: a thousandth of a sample
  std::vector<double> expected(observed.size(), 0.0);
  double pdfIntegral = 0.0;
  for (int iy = 0; iy < ny; ++iy) {
    const double y0 = domain.lo.y + iy * binHeight, y1 = iy + 1 == ny ? domain.hi.y : y0 + binHeight;
    for (int ix = 0; ix < nx; ++ix) {
      const double x0 = domain.lo.x + ix * binWidth, x1 = ix + 1 == nx ? domain.hi.x : x0 + binWidth;
      const auto row = [&](double y) {
        return adaptiveSimpson([&](double x) { return density(x, y); }, x0, x1, eps / (y1 - y0),
                               options.integrationPanels, options.integrationDepth);
      };
      const double mass =
          adaptiveSimpson(row, y0, y1, eps, options.integrationPanels, options.integrationDepth);
      pdfIntegral += mass;
      expected[static_cast<std::size_t>(iy * nx + ix)] = mass * n;
    }
  }
  dumpHistograms(options.name, observed, expected, nx);

  // Pool the cells with small expectations (smallest first) into one category.
  std::vector<std::size_t> order(observed.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double strays = 0.0, statistic = 0.0, poolObserved = 0.0, poolExpected = 0.0;
  int categories = 0;
  for (std::size_t i : order) {
    if (expected[i] <= 0.0) {
      strays += observed[i];
    } else if (expected[i] < kMinExpected || (poolExpected > 0.0 && poolExpected < kMinExpected)) {
      poolObserved += observed[i];
      poolExpected += expected[i];
    } else {
      const double d = observed[i] - expected[i];
      statistic += d * d / expected[i];
      ++categories;
    }
  }
  if (poolExpected > 0.0) {
    const double d = poolObserved - poolExpected;
    statistic += d * d / poolExpected;
    ++categories;
  }

  Chi2Result result;
  result.statistic = statistic;
  result.dof = categories - 1;
  result.pValue = result.dof > 0 ? chiSquareUpperTail(statistic, result.dof) : 0.0;
  result.pdfIntegral = pdfIntegral;
  result.sampleFraction = static_cast<double>(produced) / n;
  const double alpha = 1.0 - std::pow(1.0 - options.significance, 1.0 / options.testCount);

  std::string reasons;
  if (invalid > 0) {
    reasons += "; " + std::to_string(invalid) + " samples were not finite or outside the domain";
  }
  if (badDensity) reasons += "; the pdf is negative or not finite somewhere";
  if (static_cast<double>(zeroPdf) > kStrayFraction * n) {
    reasons += "; " + std::to_string(zeroPdf) + " samples where the pdf is 0 or not finite";
  }
  if (strays > kStrayFraction * n) {
    reasons += "; " + format("%.0f", strays) + " samples in bins where the integrated pdf is 0";
  }
  const double f = result.sampleFraction;
  if (std::abs(pdfIntegral - f) > kIntegralTolerance + 5.0 * std::sqrt(f * (1.0 - f) / n)) {
    reasons += "; the pdf integrates to " + format("%.5f", pdfIntegral) + " but " + format("%.5f", f) +
               " of the calls produced a sample";
  }
  if (result.dof < 1) {
    reasons += "; too few populated bins for a test";
  } else if (result.pValue < alpha) {
    reasons += "; the histogram does not match the pdf (p < " + format("%.3g", alpha) + ")";
  }
  result.passed = reasons.empty();
  result.message = options.name + (result.passed ? ": accepted" : ": REJECTED") + reasons +
                   format(" [chi2 = %.1f", statistic) + ", dof = " + std::to_string(result.dof) +
                   format(", p = %.4g", result.pValue) + format(", significance %.3g (Sidak over ", alpha) +
                   std::to_string(options.testCount) + format(" tests), pdf integral %.5f", pdfIntegral) +
                   format(", sample fraction %.5f]", f);
  return result;
}

}  // namespace

Chi2Result chi2TestSphere(const DirectionSampler& sampler, const DirectionPdf& pdf,
                          const Chi2Options& options) {
  const bool byTheta = options.sphereBinning == SphereBinning::Theta;
  Domain domain;
  domain.lo = {-kPi, byTheta ? 0.0 : -1.0};
  domain.hi = {kPi, byTheta ? kPi : 1.0};
  domain.draw = [&](PCG32& rng) {
    Draw d;
    const std::optional<glm::vec3> w = sampler(rng);
    if (!w) return d;
    const glm::dvec3 v(*w);
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) ||
        std::abs(glm::length(v) - 1.0) > kUnitLengthTolerance) {
      d.kind = Draw::Kind::Invalid;
      return d;
    }
    const double z = std::clamp(v.z, -1.0, 1.0);
    d.kind = Draw::Kind::Point;
    d.p = {std::atan2(v.y, v.x), byTheta ? std::acos(z) : z};
    d.pdfAtPoint = pdf(*w);
    return d;
  };
  domain.density = [&](double phi, double y) {
    const double cosTheta = byTheta ? std::cos(y) : y;
    const double sinTheta = byTheta ? std::sin(y) : std::sqrt(std::max(0.0, 1.0 - y * y));
    const glm::vec3 w(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    // d omega = d phi d cos(theta) = sin(theta) d phi d theta.
    return pdf(w) * (byTheta ? sinTheta : 1.0);
  };
  return runTest(domain, options);
}

Chi2Result chi2TestSquare(const PlanarSampler& sampler, const PlanarPdf& pdf, const Chi2Options& options) {
  Domain domain;
  domain.lo = {0.0, 0.0};
  domain.hi = {1.0, 1.0};
  domain.draw = [&](PCG32& rng) {
    Draw d;
    const std::optional<glm::vec2> p = sampler(rng);
    if (!p) return d;
    if (!(p->x >= 0.0f && p->x <= 1.0f && p->y >= 0.0f && p->y <= 1.0f)) {
      d.kind = Draw::Kind::Invalid;
      return d;
    }
    d.kind = Draw::Kind::Point;
    d.p = glm::dvec2(*p);
    d.pdfAtPoint = pdf(*p);
    return d;
  };
  domain.density = [&](double x, double y) {
    return pdf(glm::vec2(static_cast<float>(x), static_cast<float>(y)));
  };
  return runTest(domain, options);
}

double chiSquareUpperTail(double statistic, int dof) {
  const double a = 0.5 * dof, x = 0.5 * statistic;
  if (x <= 0.0) return 1.0;
  // Q(a, x) = Gamma(a, x) / Gamma(a); both expansions carry the factor x^a e^-x / Gamma(a).
  const double prefactor = std::exp(a * std::log(x) - x - std::lgamma(a));
  if (x < a + 1.0) {
    // P(a, x) = prefactor * sum_k x^k / (a (a+1) ... (a+k)).
    double term = 1.0 / a, sum = term;
    for (int k = 1; k < 100000 && term > sum * 1e-17; ++k) {
      term *= x / (a + k);
      sum += term;
    }
    return std::clamp(1.0 - prefactor * sum, 0.0, 1.0);
  }
  // Q(a, x) = prefactor * 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))), modified Lentz.
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::clamp(prefactor * h, 0.0, 1.0);
}

}  // namespace iblkit::test
