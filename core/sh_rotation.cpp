#include "core/sh_rotation.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/environment_sh.h"

namespace iblkit {
namespace {

using Matrix9 = std::array<std::array<double, kShCoefficients>, kShCoefficients>;

// Solves G X = B in place (B becomes X) by Gauss-Jordan elimination with partial pivoting; G is the
// Gram matrix of the basis at the fit directions, symmetric positive definite.
void solve(Matrix9 g, Matrix9& b) {
  for (int col = 0; col < kShCoefficients; ++col) {
    int pivot = col;
    for (int row = col + 1; row < kShCoefficients; ++row)
      if (std::abs(g[row][col]) > std::abs(g[pivot][col])) pivot = row;
    std::swap(g[col], g[pivot]);
    std::swap(b[col], b[pivot]);
    for (int row = 0; row < kShCoefficients; ++row) {
      if (row == col) continue;
      const double factor = g[row][col] / g[col][col];
      for (int k = 0; k < kShCoefficients; ++k) {
        g[row][k] -= factor * g[col][k];
        b[row][k] -= factor * b[col][k];
      }
    }
  }
  for (int row = 0; row < kShCoefficients; ++row)
    for (int k = 0; k < kShCoefficients; ++k) b[row][k] /= g[row][row];
}

}  // namespace

SphericalHarmonics9 rotateShAboutY(const SphericalHarmonics9& sh, float degrees) {
  const double angle = double(degrees) * 3.14159265358979323846 / 180.0;
  const float c = float(std::cos(angle)), s = float(std::sin(angle));
  // R_y(-angle) d, the direction the rotated function reads the original at.
  auto unrotate = [&](const glm::vec3& d) { return glm::vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z); };
  // Least squares: G = sum_i Y(d_i) Y(d_i)^T, right-hand side column j = sum_i Y(d_i) Y_j(R^-1 d_i);
  // the solution's column j holds the coefficients of Y_j(R^-1 d).
  Matrix9 gram{}, rhs{};
  for (const glm::vec3& d : fibonacciSphere(32)) {
    const ShBasis9 y = shBasis9(d), rotated = shBasis9(unrotate(d));
    for (int k = 0; k < kShCoefficients; ++k)
      for (int j = 0; j < kShCoefficients; ++j) {
        gram[k][j] += double(y[k]) * y[j];
        rhs[k][j] += double(y[k]) * rotated[j];
      }
  }
  solve(gram, rhs);
  SphericalHarmonics9 result;
  for (int k = 0; k < kShCoefficients; ++k) {
    glm::dvec3 sum(0.0);
    for (int j = 0; j < kShCoefficients; ++j) sum += rhs[k][j] * glm::dvec3(sh.coefficients[std::size_t(j)]);
    result.coefficients[std::size_t(k)] = glm::vec3(sum);
  }
  return result;
}

}  // namespace iblkit
