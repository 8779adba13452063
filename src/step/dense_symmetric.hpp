// Symmetric dense eigenvalue building blocks of the small-model eigensolvers (LAPACK). Pure: no MPI,
// no PETSc objects; matrices are column-major n x n.
#pragma once
#include <functional>
#include <vector>

namespace sinew {

/// Eigen-decomposition of the symmetric a (n x n, overwritten by the eigenvectors); ascending w
/// (LAPACK dsyevd). False when LAPACK fails.
bool symmetricEigen(std::vector<double>& a, int n, std::vector<double>& w);

/// Generalized symmetric-definite H z = lambda G z (G positive definite; H overwritten by Z, G by its
/// Cholesky factor); ascending w (LAPACK dsygvd). False when G is not positive definite.
bool symmetricDefiniteEigen(std::vector<double>& H, std::vector<double>& G, int n, std::vector<double>& w);

/// The eigenvector columns wanted, given the ascending eigenvalues w: indices into w, in the order wanted.
using PickColumns = std::function<std::vector<int>(const std::vector<double>& w)>;

/// symmetricEigen with the eigenvectors of the columns pick(w) only, into Z (n x pick(w).size(), in
/// that order), bit for bit those of symmetricEigen: dsyevd's own steps (dsytrd, dstedc), then its
/// back-transformation (dormtr) on the columns from the lowest picked one on instead of all n (the
/// saving when the wanted eigenvalues are the largest; up to n = 63, where it is column by column).
/// a is overwritten.
bool symmetricEigenSelected(std::vector<double>& a, int n, std::vector<double>& w, const PickColumns& pick,
                            std::vector<double>& Z);

/// B = L L^T for the symmetric positive semidefinite B (n x n), L n x r with r its numerical rank:
/// Cholesky with complete pivoting (LAPACK dpstrf, stopping at a pivot below n eps max B_ii), about
/// n^3/3 operations. Checked on a probe vector: where B - L L^T exceeds round-off (B not semidefinite),
/// L holds sqrt(d_j) q_j of B's eigenpairs with d_j > n eps max d instead. False when both fail.
bool semidefiniteFactor(const std::vector<double>& B, int n, std::vector<double>& L, int& r);

}  // namespace sinew
