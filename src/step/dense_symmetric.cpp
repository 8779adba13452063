#include "step/dense_symmetric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

extern "C" {
void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info);
void dsygvd_(const int* itype, const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* b,
             const int* ldb, double* w, double* work, const int* lwork, int* iwork, const int* liwork, int* info);
double dlamch_(const char* cmach);
double dlansy_(const char* norm, const char* uplo, const int* n, const double* a, const int* lda, double* work);
void dlascl_(const char* type, const int* kl, const int* ku, const double* cfrom, const double* cto, const int* m,
             const int* n, double* a, const int* lda, int* info);
void dsytrd_(const char* uplo, const int* n, double* a, const int* lda, double* d, double* e, double* tau, double* work,
             const int* lwork, int* info);
void dstedc_(const char* compz, const int* n, double* d, double* e, double* z, const int* ldz, double* work,
             const int* lwork, int* iwork, const int* liwork, int* info);
void dormtr_(const char* side, const char* uplo, const char* trans, const int* m, const int* n, const double* a,
             const int* lda, const double* tau, double* c, const int* ldc, double* work, const int* lwork, int* info);
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

bool symmetricEigenSelected(std::vector<double>& a, int n, std::vector<double>& w, const PickColumns& pick,
                            std::vector<double>& Z) {
  w.assign(n, 0.0);
  Z.clear();
  if (n == 0) return true;
  if (n == 1) {
    w[0] = a[0];
    Z.assign(pick(w).size(), 1.0);
    return true;
  }
  int info = 0, lwork = -1, liwork = -1, iq = 0;
  double wq = 0;
  dsyevd_("V", "L", &n, a.data(), &n, w.data(), &wq, &lwork, &iq, &liwork, &info);
  lwork = static_cast<int>(wq);
  liwork = iq;
  // dsyevd (jobz 'V', uplo 'L') step by step, with its workspace (dsytrd's and dormtr's blocking
  // depend on the sizes) laid out as it does: e, tau, the tridiagonal form's eigenvectors V, the rest
  const std::unique_ptr<double[]> work(new double[lwork]);  // uninitialized: LAPACK only writes it first
  const std::unique_ptr<int[]> iwork(new int[liwork]);
  const double smlnum = dlamch_("Safe minimum") / dlamch_("Precision");
  const double rmin = std::sqrt(smlnum), rmax = std::sqrt(1.0 / smlnum);
  const double anrm = dlansy_("M", "L", &n, a.data(), &n, work.get());
  double scale = 0.0;  // to the safe range
  if (anrm > 0.0 && anrm < rmin) scale = rmin / anrm;
  else if (anrm > rmax) scale = rmax / anrm;
  const int zero = 0;
  const double one = 1.0;
  if (scale != 0.0) dlascl_("L", &zero, &zero, &one, &scale, &n, &n, a.data(), &n, &info);
  double* e = work.get();
  double* tau = e + n;
  double* V = tau + n;
  double* rest = V + static_cast<size_t>(n) * n;
  const int lwork1 = lwork - 2 * n, lwork2 = lwork1 - n * n;
  dsytrd_("L", &n, a.data(), &n, w.data(), e, tau, V, &lwork1, &info);
  dstedc_("I", &n, w.data(), e, V, &n, rest, &lwork2, iwork.get(), &liwork, &info);
  if (info != 0) return false;
  if (scale != 0.0) {
    const double inv = one / scale;
    for (double& x : w) x *= inv;
  }
  const std::vector<int> cols = pick(w);
  if (cols.empty()) return true;
  // the reflectors applied to the columns [first, n), first the start of the group of four holding the
  // lowest selected column: the BLAS dot products (OpenBLAS's dgemv sums a column differently in
  // its groups of four columns and among the last n mod 4, and LAPACK's dlarf leaves out trailing
  // zero columns) are then those of dsyevd's n columns, and the vectors dsyevd's bit for bit. That
  // holds for dormtr's unblocked, column-by-column back-transformation, the one dsyevd's workspace
  // gives up to n = 63 (LAPACK 3.7 on: blocks of two reflectors need 2 n + 65 * 64 doubles, and their
  // size depends on the number of columns), and the one a workspace of k doubles gives the k columns;
  // for larger n all columns, as dsyevd
  const bool columnByColumn = lwork2 < 2 * n + 65 * 64;
  const int first = columnByColumn ? 4 * (*std::min_element(cols.begin(), cols.end()) / 4) : 0, k = n - first;
  const int lworkBack = columnByColumn ? k : lwork2;
  std::vector<double> Vs(V + static_cast<size_t>(first) * n, V + static_cast<size_t>(n) * n);
  dormtr_("L", "L", "N", &n, &k, a.data(), &n, tau, Vs.data(), &n, rest, &lworkBack, &info);
  if (info != 0) return false;
  Z.resize(static_cast<size_t>(n) * cols.size());
  for (size_t c = 0; c < cols.size(); ++c)
    std::copy_n(&Vs[static_cast<size_t>(cols[c] - first) * n], n, &Z[c * n]);
  return true;
}

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
