// Corotated Newton matrix of ANCF cables: the element blocks of the last assembled Newton matrix,
// kept and turned with their elements, as a matrix, an element-wise operator and node turns.
//
// A Jacobian kept across Newton iterations and time steps goes stale on a fine cable as its elements
// turn: an element's bending stiffness EI/l^3 exceeds its axial stiffness EA/l by EI/(EA l^2) (9e5 for
// A1 at 65536 elements), and a rotation by d theta moves the bending stiffness into the element's
// former axial direction, and a kept matrix stops contracting Newton (estimate d theta ~ EA l^2/EI,
// 1e-6 rad there; measured, A1g: kept matrices stalled from a turn of 2.3e-4 rad; docs/performance.md,
// "Why 65536 elements cost more per element, and what was done"). The element blocks themselves are
// objective, B(Q q) = Q B(q) Q^T, so the kept blocks rotated by each element's own rotation are the
// current Newton matrix up to the elements' deformation since they were kept. Rotating per node
// instead breaks the blocks' translation invariance (neighbouring nodes turn by different angles) and
// is worse than not rotating at all on coarser cables as a matrix; as a preconditioner of the
// element-wise product it serves fine cables (turnToIterate, rotateNodes; node_rotated_pc.hpp).
#pragma once

#include <petscmat.h>

#include <vector>

#include "assembly/assembler.hpp"

namespace sinew {

class CorotatedNewtonMatrix final : public NewtonBlockSink {
 public:
  /// Keeps the blocks of every Assembler::dynamicJacobian of `assembler` from now on (it becomes
  /// the assembler's block sink until destroyed). On a model of ANCF cables only the Newton matrix
  /// is then set from the kept blocks in one COO call (no MatSetValuesLocal per element block).
  explicit CorotatedNewtonMatrix(Assembler& assembler);
  ~CorotatedNewtonMatrix() override;
  CorotatedNewtonMatrix(const CorotatedNewtonMatrix&) = delete;
  CorotatedNewtonMatrix& operator=(const CorotatedNewtonMatrix&) = delete;

  /// The kept blocks cover every element (all are ANCF cables, the last dynamicJacobian kept them).
  bool valid() const { return valid_; }
  /// J from the blocks kept by the last dynamicJacobian(), each rotated by the change of its element's
  /// mean-slope direction since (an 8 x 8 block turns every 2-vector pair: positions and slopes),
  /// plus the node terms of dynamicJacobian (nodal masses with the kept shiftA, slope torques at U):
  /// the translation part of the mass term is isotropic. No element kernel runs. Logged as SinewCorotJac.
  PetscErrorCode assemble(Vec U, const LoadState& ls, Mat J);
  /// y = J x for the Newton matrix last built from the kept blocks (dynamicJacobian or assemble),
  /// applied element by element: each block to its element's part of x turned back into the frame
  /// the block was kept in, the result turned forward; the first node's translation is applied
  /// exactly (shiftA M_e, invariant under the turn).
  PetscErrorCode apply(Vec x, Vec y);
  /// The largest turn (rad) of an element at U away from the rotation its block has in the current
  /// Newton matrix (collective).
  PetscErrorCode turn(Vec U, const LoadState& ls, double* turn);
  /// Turns the Newton matrix's element blocks to the iterate U (apply() then applies the kept blocks
  /// rotated by each element's turn at U) and computes every owned node's slope turn since the
  /// Newton matrix was built (rotateNodes; collective).
  PetscErrorCode turnToIterate(Vec U, const LoadState& ls);
  /// y = R x (back = false) or R^T x on the owned unknowns: R turns each owned ANCF node's position
  /// and slope pair by the node's turn since the Newton matrix was built (turnToIterate); pairs with
  /// a constrained unknown are not turned. x and y: arrays of the owned unknowns (may alias).
  void rotateNodes(const double* x, double* y, bool back) const;

  // NewtonBlockSink (Assembler::dynamicJacobian)
  bool setsMatrix() const override { return coo_; }
  void start(double shiftA) override;
  void element(std::size_t e, const LocalElement& el, const double* q, const double* K) override;
  void nodeTerms(const LoadState& ls) override;
  PetscErrorCode setMatrix(Mat J) override { return setValues(J, false); }

 private:
  /// cos and sin of element e's turn since its block was kept: d0 . d and d0 x d of its mean-slope
  /// directions (node states of the assembler's last evaluation).
  void turnSinceKept(std::size_t e, double* c, double* s) const;
  /// Node terms of the Newton matrix (nodal masses with shiftA, slope torques at the current states).
  void keepNodeTerms(const LoadState& ls, double shiftA);
  /// Records the owned nodes' slope directions of the current states (a Newton matrix was built).
  void keepNodeDirections();
  /// COO pattern on J (once per matrix): element blocks, then per owned ANCF node its two
  /// translation diagonals (nodal mass) and its 2 x 2 slope block (slope torque).
  PetscErrorCode prepareCOO(Mat J);
  /// J = the kept blocks (each rotated by cs_ with rotate) plus the node terms, through the COO
  /// pattern of prepareCOO.
  PetscErrorCode setValues(Mat J, bool rotate);

  Assembler& asm_;
  bool coo_ = false;    ///< a model of ANCF cables only: J set from the kept blocks
  bool valid_ = false;  ///< every element's block kept
  double shiftA_ = 0;   ///< the mass factor of the kept blocks
  std::vector<double> blocks_;     ///< 8 x 8 block per element
  std::vector<double> dir_;        ///< mean-slope direction (unit 2-vector) per element when kept
  std::vector<double> cs_;         ///< per element cos, sin of the turn the current Newton matrix applies to its kept block
  std::vector<double> nodeTerms_;  ///< per owned node: nodal mass term (2), slope torque block (4)
  std::vector<double> nodeDir0_;   ///< per owned node: unit slope direction when the Newton matrix was built
  std::vector<double> nodeCS_;     ///< per owned node: cos, sin of its slope's turn since then (turnToIterate)
  std::vector<PetscScalar> values_;  ///< COO values
};

}  // namespace sinew
