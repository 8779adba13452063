// Dense eigensolvers of small pencils A x = lambda B x (LAPACK), giving the pairs SLEPc's
// shift-and-invert about a target sigma gives: lambda in SLEPc's order (nearest |lambda - sigma|
// first). Both pencils are equilibrated first (D A D, D B D with D = 1/sqrt(row max |A|)). Infinite eigenvalues
// (theta = 0: the zero-mass directions of constraint multipliers) are left out, as SLEPc's
// purification does. Pure: no MPI, no PETSc objects; matrices are column-major n x n.
#pragma once
#include <functional>
#include <vector>

namespace sinew {

struct DenseEigenpairs {
  int n = 0;                     ///< order of the pencil
  bool singular = false;         ///< A - sigma B is singular (no pairs)
  std::vector<double> re, im;    ///< eigenvalues lambda, nearest to sigma first (im: general pencils)
  std::vector<double> vectors;   ///< n x wanted(), column-major: x of the first wanted() pairs (real part)
  /// of the first wanted() pairs: the backward error ||A x - lambda B x|| / ((||A|| + |lambda| ||B||) ||x||)
  /// (infinity norms of A, B), the dense solver's accuracy figure where SLEPc reports its Ritz estimate
  std::vector<double> estimate;
  int count() const { return static_cast<int>(re.size()); }
  int wanted() const { return static_cast<int>(estimate.size()); }
};

/// A symmetric, B symmetric positive semidefinite (K and M of the frequency analysis). With
/// B = L L^T (L n x rank(B): semidefiniteFactor), the finite eigenpairs are those of the symmetric
/// H = L^T (A - sigma B)^-1 L = Y Theta Y^T, x = (A - sigma B)^-1 L y / theta. Vectors of the first
/// `want` pairs (only those are computed); their estimates and Rayleigh quotients unless `estimates`
/// is false (a Rayleigh-Ritz step follows: estimate then holds `want` zeros).
DenseEigenpairs symmetricPencil(const std::vector<double>& A, const std::vector<double>& B, int n, double sigma,
                                int want, bool estimates = true);

/// Rayleigh-Ritz of the symmetric pencil (A, B) in the span of the m columns of X (n x m), given the
/// products AX = A X computed accurately (the element-wise tangent): the pairs of X^T A X z =
/// lambda X^T B X z (X^T B X positive definite), x = X z, nearest to sigma first; vectors and
/// estimates (normA: ||A||_inf) of the first `want`.
DenseEigenpairs ritzPairs(const std::vector<double>& X, const std::vector<double>& AX, const std::vector<double>& B,
                          int n, int m, double sigma, double normA, int want);

/// A, B general (K_m and -K_g of the buckling analysis): every finite eigenpair by QZ (LAPACK
/// dggev; backward stable, where T = (A - sigma B)^-1 B would carry eps cond(A)), complex ones as
/// conjugate pairs; x of unit 2-norm, the real part of a complex pair's vector.
DenseEigenpairs generalPencil(const std::vector<double>& A, const std::vector<double>& B, int n, double sigma,
                              int want);

/// How many of the pairs (eigenvalues nearest to sigma first) need their vectors.
using WantedPairs = std::function<int(const std::vector<double>& re, const std::vector<double>& im)>;

/// generalPencil with vectors for the first wanted(re, im) pairs only: QZ for the eigenvalues alone,
/// then each wanted real pair's right and left vectors by inverse iteration from the LU of
/// A - lambda B, lambda their two-sided Rayleigh quotient (the same pairs to round-off, for a fraction
/// of QZ with vectors when few are wanted); complex pairs among them: generalPencil's QZ vectors.
DenseEigenpairs generalPencil(const std::vector<double>& A, const std::vector<double>& B, int n, double sigma,
                              const WantedPairs& wanted);

/// A, B symmetric (K_m and -K_g of the buckling analysis, to round-off), A positive definite on the
/// null space of its constraint rows (rows i with A_ii = 0 and B's row zero: the multipliers of
/// rigid elements and modes, coupling to the others through C = A(c, u)): every finite pair, as
/// generalPencil gives, by the symmetric-definite reduction instead of QZ. With Z an orthonormal
/// basis of null(C), x_u = Z v and Z^T B Z v = (1/lambda) Z^T A Z v (LAPACK dsygvd: Cholesky of
/// Z^T A Z); the multipliers of x by least squares from the rows u, lambda the Rayleigh quotient
/// x^T A x / x^T B x. False (out untouched) when the pencil is not symmetric to 1e-13 relative or
/// Z^T A Z is not positive definite: then use generalPencil. Vectors, estimates and Rayleigh quotients
/// for the first wanted(re, im) pairs only (re: the reduced problem's eigenvalues, nearest to sigma
/// first), as generalPencil.
bool symmetricDefinitePencil(const std::vector<double>& A, const std::vector<double>& B, int n, double sigma,
                             const WantedPairs& wanted, DenseEigenpairs& out);

/// Flips x (length n) so that its largest component (the first among ties) is positive.
void fixSign(double* x, int n);

}  // namespace sinew
