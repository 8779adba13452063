// The dense eigensolver kernels (src/step/dense_eigen.hpp) on pencils with known eigenpairs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "step/dense_eigen.hpp"
#include "step/dense_symmetric.hpp"

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

namespace {
// A buckling-like pencil with a multiplier: K (3 springs, SPD) on u = (u1, u2, u3), the constraint
// u1 - u3 = 0 as a fourth row/column (A_44 = 0, B's row 4 zero), B = -K_g symmetric indefinite
// (or, `skew` != 0, nonsymmetric as the geometric stiffness of applied moments).
void constrainedPencil(double skew, std::vector<double>& A, std::vector<double>& B) {
  A = mat(4, {4, -1, 0, 1, -1, 3, -1, 0, 0, -1, 2, -1, 1, 0, -1, 0});
  B = mat(4, {1, 0.5 + skew, 0, 0, 0.5, -2, 0.25, 0, 0, 0.25, 1.5, 0, 0, 0, 0, 0});
}

void expectSamePairs(const DenseEigenpairs& p, const DenseEigenpairs& q, int vectors) {
  ASSERT_EQ(p.count(), q.count());
  for (int j = 0; j < p.count(); ++j) {
    EXPECT_NEAR(p.re[j], q.re[j], 1e-13 * std::abs(q.re[j])) << "pair " << j;
    EXPECT_NEAR(p.im[j], q.im[j], 1e-13 * std::abs(q.re[j])) << "pair " << j;
  }
  for (int j = 0; j < vectors; ++j)
    for (int i = 0; i < p.n; ++i)
      EXPECT_NEAR(p.vectors[static_cast<size_t>(j) * p.n + i], q.vectors[static_cast<size_t>(j) * q.n + i], 1e-12)
          << "vector " << j << " entry " << i;
}
// every pair found
const sinew::WantedPairs all = [](const std::vector<double>& re, const std::vector<double>&) {
  return static_cast<int>(re.size());
};
}  // namespace

// The symmetric-definite reduction (null space of the multiplier row, dsygvd) gives QZ's pairs:
// eigenvalues, unit vectors with the multiplier's component, nearest to 0 first.
TEST(DenseEigen, SymmetricDefinitePencilIsQZ) {
  std::vector<double> A, B;
  constrainedPencil(0.0, A, B);
  DenseEigenpairs sym;
  ASSERT_TRUE(sinew::symmetricDefinitePencil(A, B, 4, 0.0, all, sym));
  const DenseEigenpairs qz = sinew::generalPencil(A, B, 4, 0.0, 4);
  EXPECT_EQ(sym.count(), 2);  // 3 unknowns - 1 constraint
  expectSamePairs(sym, qz, 2);
  EXPECT_LT(sym.estimate[0], 1e-15);
}

// Not symmetric (B carries a skew part), or A not definite on the null space: not this path.
TEST(DenseEigen, SymmetricDefinitePencilRefusesOtherPencils) {
  std::vector<double> A, B;
  constrainedPencil(0.1, A, B);
  DenseEigenpairs out;
  EXPECT_FALSE(sinew::symmetricDefinitePencil(A, B, 4, 0.0, all, out));
  constrainedPencil(0.0, A, B);
  for (double& a : A) a = -a;  // negative definite on the null space
  EXPECT_FALSE(sinew::symmetricDefinitePencil(A, B, 4, 0.0, all, out));
  EXPECT_EQ(out.count(), 0);
}

// Vectors of the wanted pairs only (eigenvalues by the reduced standard problem, vectors by inverse
// iteration): QZ's pairs on a nonsymmetric pencil; the others get no vector.
TEST(DenseEigen, GeneralPencilWantedIsQZ) {
  std::vector<double> A, B;
  constrainedPencil(0.1, A, B);
  const DenseEigenpairs qz = sinew::generalPencil(A, B, 4, 0.0, 4);
  int asked = -1;
  const DenseEigenpairs p = sinew::generalPencil(A, B, 4, 0.0, [&](const std::vector<double>& re, const std::vector<double>&) {
    asked = static_cast<int>(re.size());
    return 1;
  });
  EXPECT_EQ(asked, qz.count());
  EXPECT_EQ(p.wanted(), 1);
  expectSamePairs(p, qz, 1);
}

// B = L L^T by pivoted Cholesky: a consistent-mass-like semidefinite B with a zero row and column (a
// multiplier) and a rank-one coupling gives L of B's rank whose product is B to round-off.
TEST(DenseSymmetric, SemidefiniteFactorOfSingularMass) {
  const int n = 4;
  const auto B = mat(n, {2, 1, 0, 1, 1, 2, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1});  // rows 1, 2, 4 rank 3, row 3 zero
  std::vector<double> L;
  int r = -1;
  ASSERT_TRUE(sinew::semidefiniteFactor(B, n, L, r));
  EXPECT_EQ(r, 3);
  double worst = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double v = 0;
      for (int c = 0; c < r; ++c) v += L[static_cast<size_t>(c) * n + i] * L[static_cast<size_t>(c) * n + j];
      worst = std::max(worst, std::abs(v - B[static_cast<size_t>(j) * n + i]));
    }
  EXPECT_LT(worst, 1e-15);  // measured 4.4e-16
}

// An indefinite B (not a mass) is not taken from a truncated Cholesky, which would stop at the
// negative pivot with L L^T = [[1, 2], [2, 4]]: the probe sees the mismatch and the fallback keeps B's
// positive eigenpair, eigenvalue 3 with (1, 1)/sqrt(2): L L^T = 1.5 everywhere.
TEST(DenseSymmetric, SemidefiniteFactorFallsBackOnIndefinite) {
  const int n = 2;
  const auto B = mat(n, {1, 2, 2, 1});
  std::vector<double> L;
  int r = -1;
  ASSERT_TRUE(sinew::semidefiniteFactor(B, n, L, r));
  EXPECT_EQ(r, 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) EXPECT_NEAR(L[i] * L[j], 1.5, 1e-14) << i << " " << j;
}

// symmetricEigenSelected gives symmetricEigen's eigenvalues and, of the picked columns, its
// eigenvectors bit for bit: a dense matrix picking the largest from several on (54 x 54 is the
// crosshinge's reduced order, where the frequencies pick 28; 63 is the largest order whose
// back-transformation goes column by column, 64 and 100 have dormtr's blocked one, on all columns),
// and a reducible one (two uncoupled blocks: tridiagonal eigenvectors with exact zeros, which
// LAPACK's back-transformation treats apart).
TEST(DenseSymmetric, SelectedEigenvectorsAreTheFullOnesBitForBit) {
  for (const int n : {54, 63, 64, 100})
  for (const bool reducible : {false, true}) {
    std::vector<double> A(static_cast<size_t>(n) * n, 0.0);
    for (int j = 0; j < n; ++j)
      for (int i = j; i < n; ++i) {
        const bool coupled = !reducible || (i < 20) == (j < 20);
        const double v = coupled ? std::sin(1.0 + 0.37 * i + 1.91 * j) + (i == j ? 0.1 * i : 0.0) : 0.0;
        A[static_cast<size_t>(j) * n + i] = A[static_cast<size_t>(i) * n + j] = v;
      }
    for (const int lowest : {26, 3, 0, 53}) {
      std::vector<double> full(A), w, a(A), ws, Z;
      ASSERT_TRUE(sinew::symmetricEigen(full, n, w));
      std::vector<int> picked;
      const auto pick = [&](const std::vector<double>&) {
        for (int j = n - 1; j >= lowest; --j) picked.push_back(j);  // largest first
        return picked;
      };
      ASSERT_TRUE(sinew::symmetricEigenSelected(a, n, ws, pick, Z));
      EXPECT_EQ(w, ws);
      ASSERT_EQ(Z.size(), static_cast<size_t>(n) * picked.size());
      for (size_t c = 0; c < picked.size(); ++c)
        for (int i = 0; i < n; ++i)
          ASSERT_EQ(Z[c * n + i], full[static_cast<size_t>(picked[c]) * n + i])
              << n << (reducible ? " reducible" : " dense") << ", from " << lowest << ": column " << picked[c] << " row " << i;
    }
  }
}
