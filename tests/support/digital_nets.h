#pragma once
// Checks that point sets in [0,1)^s are (t,m,s)-nets in base 2 (Niederreiter 1992, "Random Number
// Generation and Quasi-Monte Carlo Methods", definition 4.1): for every split m - t = d_1 + ... +
// d_s, each elementary box [a_1 2^-d_1, (a_1 + 1) 2^-d_1) x ... x [a_s 2^-d_s, (a_s + 1) 2^-d_s)
// holds exactly 2^t of the 2^m points. t = 0 in 2D: every 2^-j by 2^-(m-j) box holds one point.

#include <gtest/gtest.h>

#include <vector>

namespace iblkit::test {

// points: 2^m points, each with the same number of coordinates s >= 1.
::testing::AssertionResult isNet(const std::vector<std::vector<float>>& points, int m, int t);

}  // namespace iblkit::test
