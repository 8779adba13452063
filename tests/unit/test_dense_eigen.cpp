// The dense eigensolver kernels (src/step/dense_eigen.hpp) on pencils with known eigenpairs.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "step/dense_eigen.hpp"

using sinew::DenseEigenpairs;

namespace {
// column-major n x n from row lists
std::vector<double> mat(int n, std::initializer_list<double> rows) {
  std::vector<double> a(rows), c(a.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) c[static_cast<size_t>(j) * n + i] = a[static_cast<size_t>(i) * n + j];
  return c;
}
}  // namespace

// Two masses on springs (k = 1, 1; m = 1, 1) plus a massless constraint multiplier row tying
// nothing (a third unknown with zero mass and unit stiffness): omega^2 = (3 -+ sqrt 5)/2, the
// massless unknown has an infinite eigenvalue and is left out.
TEST(DenseEigen, SymmetricPencilWithMasslessUnknown) {
  const int n = 3;
  const auto K = mat(n, {2, -1, 0, -1, 1, 0, 0, 0, 1});
  const auto M = mat(n, {1, 0, 0, 0, 1, 0, 0, 0, 0});
  const DenseEigenpairs p = sinew::symmetricPencil(K, M, n, -1e-8, 5);
  ASSERT_FALSE(p.singular);
  ASSERT_EQ(p.count(), 2);
  EXPECT_NEAR(p.re[0], (3 - std::sqrt(5.0)) / 2, 1e-14);
  EXPECT_NEAR(p.re[1], (3 + std::sqrt(5.0)) / 2, 1e-14);
  ASSERT_EQ(p.wanted(), 2);
  for (int c = 0; c < 2; ++c) {
    const double* x = &p.vectors[static_cast<size_t>(c) * n];
    EXPECT_NEAR(x[2], 0.0, 1e-14);  // the massless unknown does not move
    EXPECT_NEAR(x[0] * x[0] + x[1] * x[1], 1.0, 1e-13);  // M-normalized
    EXPECT_GT(std::abs(x[0]) > std::abs(x[1]) ? x[0] : x[1], 0.0);  // largest component positive
    EXPECT_LT(p.estimate[c], 1e-14);
  }
}

// Free-free: K singular, the shift keeps K - sigma M regular; the rigid mode has omega^2 = 0.
TEST(DenseEigen, SymmetricPencilRigidMode) {
  const int n = 2;
  const auto K = mat(n, {1, -1, -1, 1});
  const auto M = mat(n, {1, 0, 0, 1});
  const DenseEigenpairs p = sinew::symmetricPencil(K, M, n, -1e-8, 2);
  ASSERT_EQ(p.count(), 2);
  EXPECT_NEAR(p.re[0], 0.0, 1e-14);
  EXPECT_NEAR(p.re[1], 2.0, 1e-14);
}

// The nearest to the target first, negative ones included (an unstable state).
TEST(DenseEigen, OrderNearestToTarget) {
  const int n = 3;
  const auto K = mat(n, {-1, 0, 0, 0, 4, 0, 0, 0, 0.5});
  const auto M = mat(n, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  const DenseEigenpairs p = sinew::symmetricPencil(K, M, n, 0.0, 3);
  ASSERT_EQ(p.count(), 3);
  EXPECT_NEAR(p.re[0], 0.5, 1e-14);
  EXPECT_NEAR(p.re[1], -1.0, 1e-14);
  EXPECT_NEAR(p.re[2], 4.0, 1e-14);
}

// General pencil A x = mu B x (buckling K_m phi = mu (-K_g) phi): mu = 2 and -3 with a null
// direction of B (infinite mu, left out); A nonsymmetric.
TEST(DenseEigen, GeneralPencil) {
  const int n = 3;
  const auto A = mat(n, {2, 1, 0, 0, -3, 0, 0, 0, 5});
  const auto B = mat(n, {1, 0, 0, 0, 1, 0, 0, 0, 0});
  const DenseEigenpairs p = sinew::generalPencil(A, B, n, 0.0, 3);
  ASSERT_FALSE(p.singular);
  ASSERT_EQ(p.count(), 2);
  EXPECT_NEAR(p.re[0], 2.0, 1e-13);
  EXPECT_NEAR(p.re[1], -3.0, 1e-13);
  EXPECT_EQ(p.im[0], 0.0);
  const double* x = &p.vectors[0];  // mu = 2: x = (1, 0, 0)
  EXPECT_NEAR(x[0], 1.0, 1e-14);
  EXPECT_NEAR(x[1], 0.0, 1e-14);
  EXPECT_LT(p.estimate[0], 1e-15);
}

// Rayleigh-Ritz in a basis: the exact eigenvectors as basis give the exact pairs back.
TEST(DenseEigen, RitzPairsInExactBasis) {
  const int n = 2;
  const auto K = mat(n, {2, 0, 0, 8});
  const auto M = mat(n, {1, 0, 0, 2});
  const std::vector<double> X = {1, 0, 0, 1};  // columns e1, e2
  const std::vector<double> KX = K;
  const DenseEigenpairs p = sinew::ritzPairs(X, KX, M, n, 2, 0.0, 8.0, 2);
  ASSERT_EQ(p.count(), 2);
  EXPECT_NEAR(p.re[0], 2.0, 1e-14);
  EXPECT_NEAR(p.re[1], 4.0, 1e-14);
}
