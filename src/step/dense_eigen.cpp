#include "step/dense_eigen.hpp"

#include "step/dense_symmetric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

// LAPACK / BLAS (Fortran interfaces; the library linked is Debian's liblapack.so.3 alternative)
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi,
            double* vl, const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info);
void dggev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* b, const int* ldb,
            double* alphar, double* alphai, double* beta, double* vl, const int* ldvl, double* vr, const int* ldvr,
            double* work, const int* lwork, int* info);
void dgeqrf_(const int* m, const int* n, double* a, const int* lda, double* tau, double* work, const int* lwork,
             int* info);
void dorgqr_(const int* m, const int* n, const int* k, double* a, const int* lda, const double* tau, double* work,
             const int* lwork, int* info);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dgemm_(const char* ta, const char* tb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc);
}

namespace sinew {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// C (m x n) = op(A) op(B), column-major
void gemm(char ta, char tb, int m, int n, int k, const double* a, int lda, const double* b, int ldb, double* c) {
  const double one = 1.0, zero = 0.0;
  if (m > 0 && n > 0) dgemm_(&ta, &tb, &m, &n, &k, &one, a, &lda, b, &ldb, &zero, c, &m);
}

// ||A||_inf of the column-major n x n A: each row's sum of |A_ij| over j ascending, accumulated column by
// column (contiguous reads)
double normInf(const std::vector<double>& A, int n) {
  std::vector<double> r(n, 0.0);
  for (int j = 0; j < n; ++j) {
    const double* a = &A[static_cast<size_t>(j) * n];
    for (int i = 0; i < n; ++i) r[i] += std::abs(a[i]);
  }
  double m = 0;
  for (double v : r) m = std::max(m, v);
  return m;
}

// Normwise backward error ||A x - lambda B x|| / ((||A|| + |lambda| ||B||) ||x||) of a complex pair
// (xr + i xi, lr + i li), given ax = A x and bx = B x (real and imaginary parts).
double backwardError(const std::vector<double>& axr, const std::vector<double>& axi, const std::vector<double>& bxr,
                     const std::vector<double>& bxi, const double* xr, const double* xi, double lr, double li,
                     double normA, double normB) {
  double rr = 0, xx = 0;
  for (size_t i = 0; i < axr.size(); ++i) {
    const double a = axr[i] - (lr * bxr[i] - li * bxi[i]), b = axi[i] - (lr * bxi[i] + li * bxr[i]);
    rr += a * a + b * b;
    xx += xr[i] * xr[i] + (xi ? xi[i] * xi[i] : 0.0);
  }
  const double scale = (normA + std::hypot(lr, li) * normB) * std::sqrt(xx);
  return scale > 0 ? std::sqrt(rr) / scale : 0.0;
}

// LU of A - sigma B in place; false when singular
bool shiftedLU(const std::vector<double>& A, const std::vector<double>& B, int n, double sigma,
               std::vector<double>& lu, std::vector<int>& piv) {
  lu.resize(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < lu.size(); ++i) lu[i] = A[i] - sigma * B[i];
  piv.assign(n, 0);
  int info = 0;
  if (n > 0) dgetrf_(&n, &n, lu.data(), &n, piv.data(), &info);
  return info == 0;
}

void luSolve(const std::vector<double>& lu, const std::vector<int>& piv, int n, int nrhs, double* b) {
  int info = 0;
  if (n > 0 && nrhs > 0) dgetrs_("N", &n, &nrhs, lu.data(), &n, piv.data(), b, &n, &info);
}

// Symmetric equilibration of a pencil: D with d_i = 1/sqrt(max_j |A0_ij|) (rows of translations,
// rotations and multipliers differ by orders of magnitude in their units), A = D A0 D, B = D B0 D into
// the n x n arrays A and B; the eigenvalues are unchanged, x = D x~.
std::vector<double> equilibrated(const std::vector<double>& A0, const std::vector<double>& B0, int n, double* A,
                                 double* B) {
  std::vector<double> d(n, 1.0);
  for (int i = 0; i < n; ++i) d[i] = std::abs(A0[i]);
  for (int j = 1; j < n; ++j) {
    const double* a0 = &A0[static_cast<size_t>(j) * n];
    for (int i = 0; i < n; ++i) d[i] = std::max(d[i], std::abs(a0[i]));
  }
  for (double& v : d) v = v > 0 ? 1.0 / std::sqrt(v) : 1.0;
  for (int j = 0; j < n; ++j) {
    const size_t o = static_cast<size_t>(j) * n;
    const double dj = d[j];
    const double *__restrict a0 = &A0[o], *__restrict b0 = &B0[o];
    double *__restrict a = &A[o], *__restrict b = &B[o];
    for (int i = 0; i < n; ++i) {
      a[i] = a0[i] * (d[i] * dj);
      b[i] = b0[i] * (d[i] * dj);
    }
  }
  return d;
}

/// An n x n scratch array that is not zeroed when made (everything in it is written before it is read).
std::unique_ptr<double[]> squareArray(int n) {
  return std::unique_ptr<double[]>(new double[std::max<size_t>(static_cast<size_t>(n) * n, 1)]);
}

/// The finite eigenvalues lambda = alpha / beta of a QZ decomposition (beta above round-off of
/// |alpha|) into out.re, out.im, nearest to sigma first; returns their QZ indices in that order.
std::vector<int> finiteEigenvalues(const std::vector<double>& ar, const std::vector<double>& ai,
                                   const std::vector<double>& beta, double sigma, DenseEigenpairs& out) {
  const int n = static_cast<int>(beta.size());
  std::vector<int> order;
  for (int j = 0; j < n; ++j)
    if (std::abs(beta[j]) > n * kEps * std::hypot(ar[j], ai[j])) order.push_back(j);
  auto dist = [&](int j) { return std::hypot(ar[j] / beta[j] - sigma, ai[j] / beta[j]); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist(a) < dist(b); });
  for (int j : order) {
    out.re.push_back(ar[j] / beta[j]);
    out.im.push_back(ai[j] / beta[j]);
  }
  return order;
}

/// x scaled to unit 2-norm (zero stays zero), its sign fixed (fixSign), into dest[0 .. x.size()).
void storeUnitVector(const std::vector<double>& x, double* dest) {
  const int n = static_cast<int>(x.size());
  double nr = 0;
  for (double v : x) nr += v * v;
  nr = std::sqrt(nr);
  for (int i = 0; i < n; ++i) dest[i] = nr > 0 ? x[i] / nr : 0.0;
  fixSign(dest, n);
}

}  // namespace

void fixSign(double* x, int n) {
  int imax = 0;
  for (int i = 1; i < n; ++i)
    if (std::abs(x[i]) > (1.0 + 1e-8) * std::abs(x[imax])) imax = i;
  if (n > 0 && x[imax] < 0)
    for (int i = 0; i < n; ++i) x[i] = -x[i];
}

DenseEigenpairs symmetricPencil(const std::vector<double>& A0, const std::vector<double>& B0, int n, double sigma,
                                int want, bool estimates) {
  DenseEigenpairs out;
  out.n = n;
  std::vector<double> A(A0.size()), B(B0.size());
  const std::vector<double> D = equilibrated(A0, B0, n, A.data(), B.data());
  std::vector<double> lu;
  std::vector<int> piv;
  if (!shiftedLU(A, B, n, sigma, lu, piv)) {
    out.singular = true;
    return out;
  }
  // B = L L^T (pivoted Cholesky; B's eigenpairs where B is not semidefinite to round-off)
  std::vector<double> L;
  int r = 0;
  if (!semidefiniteFactor(B, n, L, r)) {
    out.singular = true;
    return out;
  }
  // W = (A - sigma B)^-1 L, H = L^T W (symmetric up to round-off)
  std::vector<double> W(L), H(static_cast<size_t>(r) * r);
  luSolve(lu, piv, n, r, W.data());
  gemm('T', 'N', r, r, n, L.data(), n, W.data(), n, H.data());
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < i; ++j) {
      const double h = 0.5 * (H[static_cast<size_t>(j) * r + i] + H[static_cast<size_t>(i) * r + j]);
      H[static_cast<size_t>(j) * r + i] = H[static_cast<size_t>(i) * r + j] = h;
    }
  // finite eigenvalues (theta above round-off), nearest to sigma (largest |theta|) first; the
  // eigenvectors y of the first `want` of them
  std::vector<double> theta, Y;
  std::vector<int> order;
  const auto nearest = [&](const std::vector<double>& t) {
    double tmax = 0;
    for (double v : t) tmax = std::max(tmax, std::abs(v));
    for (int j = 0; j < r; ++j)
      if (std::abs(t[j]) > r * kEps * tmax) order.push_back(j);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(t[a]) > std::abs(t[b]); });
    return std::vector<int>(order.begin(), order.begin() + std::min<int>(want, static_cast<int>(order.size())));
  };
  if (!symmetricEigenSelected(H, r, theta, nearest, Y)) {
    out.singular = true;
    return out;
  }
  for (int j : order) out.re.push_back(sigma + 1.0 / theta[j]);
  out.im.assign(out.re.size(), 0.0);
  const int k = std::min<int>(want, out.count());
  // x_j = W y_j / theta_j
  for (int c = 0; c < k; ++c)
    for (int i = 0; i < r; ++i) Y[static_cast<size_t>(c) * r + i] /= theta[order[c]];
  out.vectors.assign(static_cast<size_t>(n) * k, 0.0);
  gemm('N', 'N', n, k, r, W.data(), n, Y.data(), r, out.vectors.data());
  for (int c = 0; c < k; ++c) {
    double* x = &out.vectors[static_cast<size_t>(c) * n];
    for (int i = 0; i < n; ++i) x[i] *= D[i];
    fixSign(x, n);
  }
  if (!estimates) {
    out.estimate.assign(k, 0.0);
    return out;
  }
  // estimate: the pair's backward error in the pencil (A, B), as the dense solver's accuracy figure
  std::vector<double> AX(static_cast<size_t>(n) * k), BX(static_cast<size_t>(n) * k), zero(n, 0.0);
  gemm('N', 'N', n, k, n, A0.data(), n, out.vectors.data(), n, AX.data());
  gemm('N', 'N', n, k, n, B0.data(), n, out.vectors.data(), n, BX.data());
  out.estimate.assign(k, 0.0);
  const double nA = normInf(A0, n), nB = normInf(B0, n);
  for (int c = 0; c < k; ++c) {
    const size_t o = static_cast<size_t>(c) * n;
    const std::vector<double> ax(AX.begin() + o, AX.begin() + o + n), bx(BX.begin() + o, BX.begin() + o + n);
    // Rayleigh quotient x^T A x / x^T B x: sigma + 1/theta carries eps theta_max / theta of the rigid
    // modes' huge theta (free-free structures); the quotient's error is quadratic in the vector's
    const double xax = std::inner_product(ax.begin(), ax.end(), &out.vectors[o], 0.0);
    const double xbx = std::inner_product(bx.begin(), bx.end(), &out.vectors[o], 0.0);
    if (xbx > 0) out.re[c] = xax / xbx;
    out.estimate[c] = backwardError(ax, zero, bx, zero, &out.vectors[o], nullptr, out.re[c], 0.0, nA, nB);
  }
  return out;
}

DenseEigenpairs ritzPairs(const std::vector<double>& X, const std::vector<double>& AX, const std::vector<double>& B,
                          int n, int m, double sigma, double normA, int want) {
  DenseEigenpairs out;
  out.n = n;
  // S = X^T A X (symmetrized), C = X^T B X
  std::vector<double> S(static_cast<size_t>(m) * m), BX(static_cast<size_t>(n) * m), C(static_cast<size_t>(m) * m);
  gemm('T', 'N', m, m, n, X.data(), n, AX.data(), n, S.data());
  gemm('N', 'N', n, m, n, B.data(), n, X.data(), n, BX.data());
  gemm('T', 'N', m, m, n, X.data(), n, BX.data(), n, C.data());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j) {
      const size_t ij = static_cast<size_t>(j) * m + i, ji = static_cast<size_t>(i) * m + j;
      S[ij] = S[ji] = 0.5 * (S[ij] + S[ji]);
      C[ij] = C[ji] = 0.5 * (C[ij] + C[ji]);
    }
  std::vector<double> lambda;
  if (!symmetricDefiniteEigen(S, C, m, lambda)) {
    out.singular = true;
    return out;
  }
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return std::abs(lambda[a] - sigma) < std::abs(lambda[b] - sigma); });
  for (int j : order) out.re.push_back(lambda[j]);
  out.im.assign(m, 0.0);
  const int k = std::min(want, m);
  std::vector<double> Z(static_cast<size_t>(m) * k);
  for (int c = 0; c < k; ++c) std::copy_n(&S[static_cast<size_t>(order[c]) * m], m, &Z[static_cast<size_t>(c) * m]);
  out.vectors.assign(static_cast<size_t>(n) * k, 0.0);
  gemm('N', 'N', n, k, m, X.data(), n, Z.data(), m, out.vectors.data());
  // estimate: backward error with A x = (A X) z, the accurate products combined
  std::vector<double> AXZ(static_cast<size_t>(n) * k), BXZ(static_cast<size_t>(n) * k), zero(n, 0.0);
  gemm('N', 'N', n, k, m, AX.data(), n, Z.data(), m, AXZ.data());
  gemm('N', 'N', n, k, m, BX.data(), n, Z.data(), m, BXZ.data());
  const double nB = normInf(B, n);
  out.estimate.assign(k, 0.0);
  for (int c = 0; c < k; ++c) {
    const size_t o = static_cast<size_t>(c) * n;
    const std::vector<double> ax(AXZ.begin() + o, AXZ.begin() + o + n), bx(BXZ.begin() + o, BXZ.begin() + o + n);
    out.estimate[c] = backwardError(ax, zero, bx, zero, &out.vectors[o], nullptr, out.re[c], 0.0, normA, nB);
    fixSign(&out.vectors[o], n);
  }
  return out;
}

DenseEigenpairs generalPencil(const std::vector<double>& A0, const std::vector<double>& B0, int n, double sigma,
                              int want) {
  DenseEigenpairs out;
  out.n = n;
  std::vector<double> A(A0.size()), B(B0.size());
  const std::vector<double> D = equilibrated(A0, B0, n, A.data(), B.data());
  // QZ of the pencil (backward stable in A and B, where T = A^-1 B would carry cond(A) eps)
  std::vector<double> ar(n), ai(n), beta(n), vr(static_cast<size_t>(n) * n), vl(vr.size());
  int info = 0, lwork = -1;
  double wq = 0;
  if (n > 0) {
    dggev_("V", "V", &n, A.data(), &n, B.data(), &n, ar.data(), ai.data(), beta.data(), vl.data(), &n, vr.data(), &n,
           &wq, &lwork, &info);
    lwork = static_cast<int>(wq);
    std::vector<double> work(std::max(lwork, 1));
    dggev_("V", "V", &n, A.data(), &n, B.data(), &n, ar.data(), ai.data(), beta.data(), vl.data(), &n, vr.data(), &n,
           work.data(), &lwork, &info);
  }
  if (info != 0) {
    out.singular = true;
    return out;
  }
  const std::vector<int> order = finiteEigenvalues(ar, ai, beta, sigma, out);
  const int k = std::min<int>(want, out.count());
  out.vectors.assign(static_cast<size_t>(n) * k, 0.0);
  out.estimate.assign(k, 0.0);
  const double nA = normInf(A0, n), nB = normInf(B0, n);
  for (int c = 0; c < k; ++c) {
    const int j = order[c];
    // a complex pair (j, j+1) has vectors vr_j +- i vr_j+1 (the first has ai > 0)
    std::vector<double> xr(n), xi(n, 0.0);
    if (ai[j] == 0.0) {
      std::copy_n(&vr[static_cast<size_t>(j) * n], n, xr.begin());
    } else {
      const bool first = ai[j] > 0;
      const int p = first ? j : j - 1;
      std::copy_n(&vr[static_cast<size_t>(p) * n], n, xr.begin());
      for (int i = 0; i < n; ++i) xi[i] = (first ? 1.0 : -1.0) * vr[static_cast<size_t>(p + 1) * n + i];
    }
    for (int i = 0; i < n; ++i) {
      xr[i] *= D[i];
      xi[i] *= D[i];
    }
    std::vector<double> axr(n), axi(n), bxr(n), bxi(n);
    gemm('N', 'N', n, 1, n, A0.data(), n, xr.data(), n, axr.data());
    gemm('N', 'N', n, 1, n, A0.data(), n, xi.data(), n, axi.data());
    gemm('N', 'N', n, 1, n, B0.data(), n, xr.data(), n, bxr.data());
    gemm('N', 'N', n, 1, n, B0.data(), n, xi.data(), n, bxi.data());
    if (ai[j] == 0.0) {  // two-sided Rayleigh quotient y^T A x / y^T B x (y = D y~): error quadratic in the vectors'
      double yax = 0, ybx = 0;
      for (int i = 0; i < n; ++i) {
        const double y = D[i] * vl[static_cast<size_t>(j) * n + i];
        yax += y * axr[i];
        ybx += y * bxr[i];
      }
      if (ybx != 0.0 && std::isfinite(yax / ybx)) out.re[c] = yax / ybx;
    }
    out.estimate[c] = backwardError(axr, axi, bxr, bxi, xr.data(), xi.data(), out.re[c], out.im[c], nA, nB);
    storeUnitVector(xr, &out.vectors[static_cast<size_t>(c) * n]);
  }
  return out;
}


namespace {

// Householder QR of the nu x m matrix a (column-major, overwritten by the factors); Q (nu x nu) formed
// (dorgqr writes all of it from the reflectors in its first m columns: not zeroed first).
bool fullQR(std::vector<double>& a, int nu, int m, std::unique_ptr<double[]>& Q) {
  std::vector<double> tau(std::max(m, 1));
  int info = 0, lwork = -1;
  double wq = 0;
  Q = squareArray(nu);
  if (m > 0) {
    dgeqrf_(&nu, &m, a.data(), &nu, tau.data(), &wq, &lwork, &info);
    lwork = std::max(static_cast<int>(wq), nu);
    const std::unique_ptr<double[]> work(new double[static_cast<size_t>(lwork)]);  // LAPACK's scratch
    dgeqrf_(&nu, &m, a.data(), &nu, tau.data(), work.get(), &lwork, &info);
    if (info != 0) return false;
    std::copy(a.begin(), a.end(), Q.get());
  }
  if (nu == 0) return true;
  lwork = -1;
  dorgqr_(&nu, &nu, &m, Q.get(), &nu, tau.data(), &wq, &lwork, &info);
  lwork = std::max(static_cast<int>(wq), nu);
  const std::unique_ptr<double[]> work(new double[static_cast<size_t>(lwork)]);
  dorgqr_(&nu, &nu, &m, Q.get(), &nu, tau.data(), work.get(), &lwork, &info);
  return info == 0;
}

// Symmetric to round-off: max |A_ij - A_ji| <= tol max |A_ij| (the strict lower triangle against
// the upper one, stopping at the first pair beyond the bound).
bool symmetricMatrix(const double* A, int n, double tol) {
  double part[4] = {0, 0, 0, 0};  // max |A_ij| in four running maxima (exact in any order)
  const size_t nn = static_cast<size_t>(n) * n, n4 = nn - nn % 4;
  for (size_t k = 0; k < n4; k += 4)
    for (int q = 0; q < 4; ++q) part[q] = std::max(part[q], std::abs(A[k + q]));
  for (size_t k = n4; k < nn; ++k) part[0] = std::max(part[0], std::abs(A[k]));
  const double amax = std::max(std::max(part[0], part[1]), std::max(part[2], part[3]));
  const double bound = tol * amax;
  for (int j = 0; j < n; ++j) {
    const double *col = A + static_cast<size_t>(j) * n, *row = A + j;  // A(:, j) and A(j, :)
    for (int i = j + 1; i < n; ++i)
      if (std::abs(col[i] - row[static_cast<size_t>(i) * n]) > bound) return false;
  }
  return true;
}

// The block M(rows, cols) into the column-major array b.
void block(const double* M, int n, const std::vector<int>& rows, const std::vector<int>& cols, double* b) {
  for (size_t c = 0; c < cols.size(); ++c)
    for (size_t r = 0; r < rows.size(); ++r) b[c * rows.size() + r] = M[static_cast<size_t>(cols[c]) * n + rows[r]];
}

// Z^T M Z (r x r, symmetrized if `symmetrize`) of the nu x nu M and the nu x r Z.
void project(const double* M, const double* Z, int nu, int r, bool symmetrize, double* P) {
  // MZ: no zeros first (dgemm with beta 0 overwrites it)
  const std::unique_ptr<double[]> MZ(new double[static_cast<size_t>(nu) * r]);
  gemm('N', 'N', nu, r, nu, M, nu, Z, nu, MZ.get());
  gemm('T', 'N', r, r, nu, Z, nu, MZ.get(), nu, P);
  for (int i = 0; i < r && symmetrize; ++i)
    for (int j = 0; j < i; ++j) {
      const size_t ij = static_cast<size_t>(j) * r + i, ji = static_cast<size_t>(i) * r + j;
      P[ij] = P[ji] = 0.5 * (P[ij] + P[ji]);
    }
}

std::vector<double> project(const double* M, const double* Z, int nu, int r, bool symmetrize) {
  std::vector<double> P(static_cast<size_t>(r) * r);
  project(M, Z, nu, r, symmetrize, P.data());
  return P;
}

}  // namespace

namespace {

// The pencil (A, B) (equilibrated, A symmetric) restricted to the null space of its constraint rows:
// c (A_ii = 0, B's row zero, A(c, c) = 0), u the others, C = A(c, u), C^T = Q R, Z = the last r
// columns of Q. False when there is no such reduction (no unknowns left, redundant constraints).
struct NullSpaceReduction {
  std::vector<int> c, u;
  std::vector<double> CT;  // the QR factors of C^T (R in its upper triangle)
  std::unique_ptr<double[]> Q, Auu, Buu;  // nu x nu
  int m = 0, nu = 0, r = 0;
  const double* Z() const { return Q.get() + static_cast<size_t>(m) * nu; }
};

bool reduceToNullSpace(const double* A, const double* B, int n, NullSpaceReduction& red) {
  std::vector<int>& c = red.c;
  std::vector<int>& u = red.u;
  for (int i = 0; i < n; ++i) {
    bool constraint = A[static_cast<size_t>(i) * n + i] == 0.0;
    for (int j = 0; j < n && constraint; ++j) constraint = B[static_cast<size_t>(j) * n + i] == 0.0;
    (constraint ? c : u).push_back(i);
  }
  for (int i : c)
    for (int j : c)
      if (A[static_cast<size_t>(j) * n + i] != 0.0) return false;
  const int m = static_cast<int>(c.size()), nu = static_cast<int>(u.size()), r = nu - m;
  red.m = m;
  red.nu = nu;
  red.r = r;
  if (r <= 0) return false;
  // C^T = Q R (nu x m), Z = the last r columns of Q: an orthonormal basis of null(C)
  std::vector<double>& CT = red.CT;
  CT.resize(static_cast<size_t>(nu) * m);
  block(A, n, u, c, CT.data());
  if (!fullQR(CT, nu, m, red.Q)) return false;
  double rmax = 0, rmin = std::numeric_limits<double>::infinity();
  for (int k = 0; k < m; ++k) {
    rmax = std::max(rmax, std::abs(CT[static_cast<size_t>(k) * nu + k]));
    rmin = std::min(rmin, std::abs(CT[static_cast<size_t>(k) * nu + k]));
  }
  if (m > 0 && rmin <= nu * kEps * rmax) return false;  // redundant constraints
  red.Auu = squareArray(nu);
  red.Buu = squareArray(nu);
  block(A, n, u, u, red.Auu.get());
  block(B, n, u, u, red.Buu.get());
  return true;
}

}  // namespace

bool symmetricDefinitePencil(const std::vector<double>& A0, const std::vector<double>& B0, int n, double sigma,
                             const WantedPairs& wanted, DenseEigenpairs& result) {
  if (n == 0 || !symmetricMatrix(B0.data(), n, 1e-13) || !symmetricMatrix(A0.data(), n, 1e-13)) return false;
  const std::unique_ptr<double[]> Ae = squareArray(n), Be = squareArray(n);
  const double *A = Ae.get(), *B = Be.get();
  const std::vector<double> D = equilibrated(A0, B0, n, Ae.get(), Be.get());
  NullSpaceReduction red;
  if (!reduceToNullSpace(A, B, n, red)) return false;
  const std::vector<int>&c = red.c, &u = red.u;
  const std::vector<double>& CT = red.CT;
  const double *Q = red.Q.get(), *Auu = red.Auu.get(), *Buu = red.Buu.get();
  const int m = red.m, nu = red.nu, r = red.r;
  const double* Z = red.Z();
  std::vector<double> Kr = project(Auu, Z, nu, r, true), Gr = project(Buu, Z, nu, r, true), w;
  // Gr v = w Kr v, w = 1/lambda; Kr not positive definite (dsygvd fails in its Cholesky): not this path
  if (!symmetricDefiniteEigen(Gr, Kr, r, w)) return false;
  DenseEigenpairs out;
  out.n = n;
  double wmax = 0;
  for (double v : w) wmax = std::max(wmax, std::abs(v));
  std::vector<int> order;
  for (int j = 0; j < r; ++j)
    if (std::abs(w[j]) > r * kEps * wmax) order.push_back(j);
  auto dist = [&](int j) { return std::abs(1.0 / w[j] - sigma); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dist(a) < dist(b); });
  for (int j : order) out.re.push_back(1.0 / w[j]);
  out.im.assign(out.re.size(), 0.0);
  const int k = std::min(wanted(out.re, out.im), out.count());
  out.vectors.assign(static_cast<size_t>(n) * k, 0.0);
  out.estimate.assign(k, 0.0);
  const double nA = normInf(A0, n), nB = normInf(B0, n);
  std::vector<double> xu(nu), rhs(nu), Ax(n), Bx(n), zero(n, 0.0);
  for (int p = 0; p < k; ++p) {
    const int j = order[p];
    gemm('N', 'N', nu, 1, r, Z, nu, &Gr[static_cast<size_t>(j) * r], r, xu.data());
    // multipliers: C^T l = lambda B_uu x_u - A_uu x_u (least squares: l = R^-1 Q_1^T rhs)
    gemm('N', 'N', nu, 1, nu, Auu, nu, xu.data(), nu, rhs.data());
    std::vector<double> bu(nu);
    gemm('N', 'N', nu, 1, nu, Buu, nu, xu.data(), nu, bu.data());
    for (int i = 0; i < nu; ++i) rhs[i] = out.re[p] * bu[i] - rhs[i];
    std::vector<double> l(m);
    gemm('T', 'N', m, 1, nu, Q, nu, rhs.data(), nu, l.data());
    for (int a = m - 1; a >= 0; --a) {
      for (int b = a + 1; b < m; ++b) l[a] -= CT[static_cast<size_t>(b) * nu + a] * l[b];
      l[a] /= CT[static_cast<size_t>(a) * nu + a];
    }
    double* x = &out.vectors[static_cast<size_t>(p) * n];
    for (int i = 0; i < nu; ++i) x[u[i]] = D[u[i]] * xu[i];
    for (int i = 0; i < m; ++i) x[c[i]] = D[c[i]] * l[i];
    double nx = 0;
    for (int i = 0; i < n; ++i) nx += x[i] * x[i];
    nx = std::sqrt(nx);
    for (int i = 0; i < n; ++i) x[i] = nx > 0 ? x[i] / nx : 0.0;
    fixSign(x, n);
    // Rayleigh quotient x^T A x / x^T B x (symmetric pencil: the two-sided quotient of the QZ path)
    gemm('N', 'N', n, 1, n, A0.data(), n, x, n, Ax.data());
    gemm('N', 'N', n, 1, n, B0.data(), n, x, n, Bx.data());
    const double xax = std::inner_product(Ax.begin(), Ax.end(), x, 0.0);
    const double xbx = std::inner_product(Bx.begin(), Bx.end(), x, 0.0);
    if (xbx != 0.0 && std::isfinite(xax / xbx)) out.re[p] = xax / xbx;
    out.estimate[p] = backwardError(Ax, zero, Bx, zero, x, nullptr, out.re[p], 0.0, nA, nB);
  }
  result = std::move(out);
  return true;
}


namespace {

// Inverse iteration for the right (transpose false) or left vector of the eigenvalue lambda of the
// equilibrated pencil (A, B), from the LU of A - lambda B: two steps v <- (A - lambda B)^-1 B v from
// `start`.
std::vector<double> inverseIteration(const double* lu, const std::vector<int>& piv,
                                     const double* B, int n, bool transpose,
                                     const std::vector<double>& start) {
  std::vector<double> v(start), bv(n);
  for (int it = 0; it < 2; ++it) {
    gemm(transpose ? 'T' : 'N', 'N', n, 1, n, B, n, v.data(), n, bv.data());
    int info = 0, one = 1;
    dgetrs_(transpose ? "T" : "N", &n, &one, lu, &n, piv.data(), bv.data(), &n, &info);
    double m = 0;
    for (double x : bv) m = std::max(m, std::abs(x));
    for (int i = 0; i < n; ++i) v[i] = m > 0 && std::isfinite(m) ? bv[i] / m : 0.0;
  }
  return v;
}

}  // namespace

namespace {

// The eigenvalues of the general n x n M (overwritten): LAPACK dgeev without vectors.
bool standardEigenvalues(double* M, int n, std::vector<double>& wr, std::vector<double>& wi) {
  int info = 0, ld = 1, lwork = -1;
  double wq = 0, dummy = 0;
  dgeev_("N", "N", &n, M, &n, wr.data(), wi.data(), &dummy, &ld, &dummy, &ld, &wq, &lwork, &info);
  lwork = std::max(static_cast<int>(wq), 4 * n);
  const std::unique_ptr<double[]> work(new double[static_cast<size_t>(lwork)]);  // LAPACK's scratch: no zeros
  dgeev_("N", "N", &n, M, &n, wr.data(), wi.data(), &dummy, &ld, &dummy, &ld, work.get(), &lwork, &info);
  return info == 0;
}

// The finite eigenvalues lambda = ar / beta + i ai / beta of the equilibrated pencil (A, B) with A
// symmetric and positive definite on the null space Z of its constraint rows: Z^T A Z = L L^T, the
// eigenvalues w = 1/lambda of the standard nonsymmetric L^-1 Z^T B Z L^-T (LAPACK dgeev, eigenvalues
// alone: a third of QZ's); the rest (constraints, w = 0) get beta = 0. False: no such reduction.
bool reducedEigenvalues(const double* A, const double* B, int n, std::vector<double>& ar,
                        std::vector<double>& ai, std::vector<double>& beta) {
  if (n == 0 || !symmetricMatrix(A, n, 1e-13)) return false;
  NullSpaceReduction red;
  if (!reduceToNullSpace(A, B, n, red)) return false;
  const int r = red.r;
  const std::unique_ptr<double[]> Lp = squareArray(r), Mp = squareArray(r);
  double *L = Lp.get(), *M = Mp.get();
  project(red.Auu.get(), red.Z(), red.nu, r, true, L);
  project(red.Buu.get(), red.Z(), red.nu, r, false, M);
  int info = 0;
  dpotrf_("L", &r, L, &r, &info);
  if (info != 0) return false;
  const double one = 1.0;
  dtrsm_("L", "L", "N", "N", &r, &r, &one, L, &r, M, &r);  // L^-1 M
  dtrsm_("R", "L", "T", "N", &r, &r, &one, L, &r, M, &r);  // (L^-1 M) L^-T
  std::vector<double> wr(r), wi(r);
  if (!standardEigenvalues(M, r, wr, wi)) return false;
  // lambda = 1/w = conj(w) / |w|^2: alpha = conj(w), beta = |w|^2
  std::fill(ar.begin(), ar.end(), 1.0);
  std::fill(ai.begin(), ai.end(), 0.0);
  std::fill(beta.begin(), beta.end(), 0.0);
  for (int j = 0; j < r; ++j) {
    ar[j] = wr[j];
    ai[j] = -wi[j];
    beta[j] = wr[j] * wr[j] + wi[j] * wi[j];
  }
  return true;
}

}  // namespace

DenseEigenpairs generalPencil(const std::vector<double>& A0, const std::vector<double>& B0, int n, double sigma,
                              const WantedPairs& wanted) {
  DenseEigenpairs out;
  out.n = n;
  const std::unique_ptr<double[]> Ae = squareArray(n), Be = squareArray(n);
  const double *A = Ae.get(), *B = Be.get();
  const std::vector<double> D = equilibrated(A0, B0, n, Ae.get(), Be.get());
  // the eigenvalues: by the reduction to a standard problem where A is symmetric and definite on the
  // constraints' null space, else QZ alone (no Schur vectors accumulated: about half of QZ with both sets)
  std::vector<double> ar(n), ai(n), beta(n), dummy(1);
  int info = 0, lwork = -1, one = 1;
  double wq = 0;
  if (reducedEigenvalues(A, B, n, ar, ai, beta)) {
    info = 0;  // the vectors below are those of the whole pencil
  } else if (n > 0) {
    std::vector<double> Aq(A, A + static_cast<size_t>(n) * n), Bq(B, B + static_cast<size_t>(n) * n);
    dggev_("N", "N", &n, Aq.data(), &n, Bq.data(), &n, ar.data(), ai.data(), beta.data(), dummy.data(), &one,
           dummy.data(), &one, &wq, &lwork, &info);
    lwork = std::max(static_cast<int>(wq), 8 * n);
    std::vector<double> work(lwork);
    dggev_("N", "N", &n, Aq.data(), &n, Bq.data(), &n, ar.data(), ai.data(), beta.data(), dummy.data(), &one,
           dummy.data(), &one, work.data(), &lwork, &info);
  }
  if (info != 0) {
    out.singular = true;
    return out;
  }
  finiteEigenvalues(ar, ai, beta, sigma, out);
  const int k = std::min(wanted(out.re, out.im), out.count());
  for (int c = 0; c < k; ++c)
    if (out.im[c] != 0.0) return generalPencil(A0, B0, n, sigma, k);  // complex pairs: QZ's own vectors
  out.vectors.assign(static_cast<size_t>(n) * k, 0.0);
  out.estimate.assign(k, 0.0);
  const double nA = normInf(A0, n), nB = normInf(B0, n);
  const size_t nn = static_cast<size_t>(n) * n;
  const std::unique_ptr<double[]> lu(new double[std::max<size_t>(nn, 1)]);  // overwritten: no zeros first
  std::vector<double> Ax(n), Bx(n), zero(n, 0.0), start(n);
  std::vector<int> piv(n);
  for (int i = 0; i < n; ++i) start[i] = 1.0 + 0.5 * std::sin(i + 1.0);  // fixed start, no special direction
  for (int c = 0; c < k; ++c) {
    // LU of A - lambda B; an exactly zero pivot: lambda moved by a few ulps
    double shift = out.re[c];
    for (int attempt = 0; attempt < 3; ++attempt) {
      for (size_t i = 0; i < nn; ++i) lu[i] = A[i] - shift * B[i];
      dgetrf_(&n, &n, lu.get(), &n, piv.data(), &info);
      if (info == 0) break;
      shift += 8 * kEps * std::max(std::abs(shift), 1.0);
    }
    std::vector<double> x = inverseIteration(lu.get(), piv, B, n, false, start),
                        y = inverseIteration(lu.get(), piv, B, n, true, start);
    for (int i = 0; i < n; ++i) {
      x[i] *= D[i];
      y[i] *= D[i];
    }
    gemm('N', 'N', n, 1, n, A0.data(), n, x.data(), n, Ax.data());
    gemm('N', 'N', n, 1, n, B0.data(), n, x.data(), n, Bx.data());
    // two-sided Rayleigh quotient y^T A x / y^T B x: error quadratic in the vectors'
    const double yax = std::inner_product(y.begin(), y.end(), Ax.begin(), 0.0);
    const double ybx = std::inner_product(y.begin(), y.end(), Bx.begin(), 0.0);
    if (ybx != 0.0 && std::isfinite(yax / ybx)) out.re[c] = yax / ybx;
    out.estimate[c] = backwardError(Ax, zero, Bx, zero, x.data(), nullptr, out.re[c], 0.0, nA, nB);
    storeUnitVector(x, &out.vectors[static_cast<size_t>(c) * n]);
  }
  return out;
}

}  // namespace sinew
