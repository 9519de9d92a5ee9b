#include "support/digital_nets.h"

#include <algorithm>
#include <cstddef>
#include <functional>

namespace iblkit::test {

::testing::AssertionResult isNet(const std::vector<std::vector<float>>& points, int m, int t) {
  const std::size_t count = std::size_t{1} << m;
  if (points.size() != count) return ::testing::AssertionFailure() << "expected " << count << " points";
  const std::size_t s = points.front().size();
  for (const std::vector<float>& p : points) {
    if (p.size() != s) return ::testing::AssertionFailure() << "points of different dimensions";
    for (float x : p)
      if (!(x >= 0.0f && x < 1.0f))
        return ::testing::AssertionFailure() << "coordinate " << x << " outside [0,1)";
  }
  if (t >= m) return ::testing::AssertionSuccess();

  // Enumerate the splits d_1 + ... + d_s = m - t; for each, count the points per box.
  std::vector<int> split(s, 0);
  const std::size_t perBox = std::size_t{1} << t;
  std::vector<std::size_t> hits(count >> t);
  std::function<::testing::AssertionResult(std::size_t, int)> check =
      [&](std::size_t axis, int left) -> ::testing::AssertionResult {
    if (axis + 1 < s) {
      for (int d = 0; d <= left; ++d) {
        split[axis] = d;
        if (::testing::AssertionResult r = check(axis + 1, left - d); !r) return r;
      }
      return ::testing::AssertionSuccess();
    }
    split[axis] = left;
    std::fill(hits.begin(), hits.end(), 0);
    for (const std::vector<float>& p : points) {
      std::size_t box = 0;
      for (std::size_t a = 0; a < s; ++a)
        box = (box << split[a]) | static_cast<std::size_t>(p[a] * static_cast<float>(1u << split[a]));
      ++hits[box];
    }
    for (std::size_t box = 0; box < hits.size(); ++box)
      if (hits[box] != perBox) {
        ::testing::AssertionResult failure = ::testing::AssertionFailure();
        failure << "box " << box << " of the split (";
        for (std::size_t a = 0; a < s; ++a) failure << (a ? ", " : "") << split[a];
        return failure << ") holds " << hits[box] << " points, not " << perBox << " (m = " << m
                       << ", t = " << t << ")";
      }
    return ::testing::AssertionSuccess();
  };
  return check(0, m - t);
}

}  // namespace iblkit::test
