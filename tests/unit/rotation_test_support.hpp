// What the rotation unit tests share: the largest entry-wise difference of two 3x3 matrices.
#pragma once
#include <algorithm>
#include <cmath>

#include "sinew/rotation.hpp"

namespace sinew::test {

inline double maxDiff(const Mat3& a, const Mat3& b) {
  double m = 0;
  for (int i = 0; i < 9; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace sinew::test
