#include "step/dense_symmetric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

extern "C" {
void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info);
void dsygvd_(const int* itype, const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* b,
             const int* ldb, double* w, double* work, const int* lwork, int* iwork, const int* liwork, int* info);
void dpstrf_(const char* uplo, const int* n, double* a, const int* lda, int* piv, int* rank, const double* tol,
             double* work, int* info);
}

namespace sinew {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// L (n x r) from B's eigenpairs with d_j > n eps max d: L_j = sqrt(d_j) q_j
bool eigenFactor(const std::vector<double>& B, int n, std::vector<double>& L, int& r) {
  std::vector<double> Q(B), d;
  if (!symmetricEigen(Q, n, d)) return false;
  const double dmax = n > 0 ? std::max(0.0, d.back()) : 0.0;
  std::vector<int> keep;
  for (int j = 0; j < n; ++j)
    if (d[j] > n * kEps * dmax) keep.push_back(j);
  r = static_cast<int>(keep.size());
  L.assign(static_cast<size_t>(n) * r, 0.0);
  for (int c = 0; c < r; ++c) {
    const double s = std::sqrt(d[keep[c]]);
    for (int i = 0; i < n; ++i) L[static_cast<size_t>(c) * n + i] = s * Q[static_cast<size_t>(keep[c]) * n + i];
  }
  return true;
}

// ||B v - L (L^T v)||_2 <= 100 n eps ||B||_F ||v||_2 for a fixed probe v without zero components
bool factorMatches(const std::vector<double>& B, const std::vector<double>& L, int n, int r) {
  std::vector<double> v(n), t(r, 0.0), res(n, 0.0);
  double vv = 0, bb = 0;
  for (int i = 0; i < n; ++i) {
    v[i] = 1.0 + 0.5 * std::sin(1.0 + 2.3 * i);
    vv += v[i] * v[i];
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double b = B[static_cast<size_t>(j) * n + i];
      res[i] += b * v[j];
      bb += b * b;
    }
  for (int c = 0; c < r; ++c)
    for (int i = 0; i < n; ++i) t[c] += L[static_cast<size_t>(c) * n + i] * v[i];
  for (int c = 0; c < r; ++c)
    for (int i = 0; i < n; ++i) res[i] -= L[static_cast<size_t>(c) * n + i] * t[c];
  double rr = 0;
  for (double x : res) rr += x * x;
  return std::sqrt(rr) <= 100.0 * n * kEps * std::sqrt(bb) * std::sqrt(vv);
}

}  // namespace

bool symmetricEigen(std::vector<double>& a, int n, std::vector<double>& w) {
  w.assign(n, 0.0);
  if (n == 0) return true;
  int info = 0, lwork = -1, liwork = -1, iq = 0;
  double wq = 0;
  dsyevd_("V", "L", &n, a.data(), &n, w.data(), &wq, &lwork, &iq, &liwork, &info);
  lwork = static_cast<int>(wq);
  liwork = iq;
  std::vector<double> work(std::max(lwork, 1));
  std::vector<int> iwork(std::max(liwork, 1));
  dsyevd_("V", "L", &n, a.data(), &n, w.data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  return info == 0;
}

bool symmetricDefiniteEigen(std::vector<double>& H, std::vector<double>& G, int n, std::vector<double>& w) {
  w.assign(n, 0.0);
  if (n == 0) return true;
  int info = 0, lwork = -1, liwork = -1, iq = 0, itype = 1;
  double wq = 0;
  dsygvd_(&itype, "V", "L", &n, H.data(), &n, G.data(), &n, w.data(), &wq, &lwork, &iq, &liwork, &info);
  lwork = static_cast<int>(wq);
  liwork = iq;
  std::vector<double> work(std::max(lwork, 1));
  std::vector<int> iwork(std::max(liwork, 1));
  dsygvd_(&itype, "V", "L", &n, H.data(), &n, G.data(), &n, w.data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  return info == 0;
}

bool semidefiniteFactor(const std::vector<double>& B, int n, std::vector<double>& L, int& r) {
  r = 0;
  L.clear();
  if (n == 0) return true;
  std::vector<double> C(B), work(2 * static_cast<size_t>(n));
  std::vector<int> piv(n);
  const double tol = -1.0;  // LAPACK's default: n eps max B_ii
  int info = 0, rank = 0;
  dpstrf_("L", &n, C.data(), &n, piv.data(), &rank, &tol, work.data(), &info);
  if (info >= 0) {
    // P^T B P = L~ L~^T with L~'s first `rank` columns: L = P L~
    r = rank;
    L.assign(static_cast<size_t>(n) * r, 0.0);
    for (int c = 0; c < r; ++c)
      for (int i = c; i < n; ++i)
        L[static_cast<size_t>(c) * n + (piv[i] - 1)] = C[static_cast<size_t>(c) * n + i];
    if (factorMatches(B, L, n, r)) return true;
  }
  return eigenFactor(B, n, L, r);
}

}  // namespace sinew
