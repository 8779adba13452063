// Two-level preconditioner for the static Newton systems of fine ANCF cables (PCSHELL).
//
// The LU factors of a fine cable's assembled tangent (condition ~ n^4) are exact except in its
// softest, smooth modes, where their error eps |L||U| is amplified up to cond * eps. A coarse
// space of cubic Hermite functions along each split scene element (one coarse element per r ~
// 2 sqrt(n) fine ones) represents exactly those modes. One application, for a residual x:
//   y1 = P Ac^-1 P^T x,  y2 = y1 + LU^-1 (x - J y1),  y = y2 + P Ac^-1 P^T (x - J y2),
// with J the element-wise operator (Assembler::applyTangent) and Ac = sum_e P_e^T J_e P_e assembled
// from the kept element blocks, each applied to its coarse functions minus their translation (the
// accuracy of applyTangent); the values are summed over ranks in the coarse matrix's fixed pattern.
// The coarse problem is small (4 unknowns per coarse node) and solved redundantly on every rank.
// Fine DOF rows of P, at arc length s = xi Lc inside coarse element (a, b):
//   position:  H1(xi) r_a + Lc H2(xi) s_a + H3(xi) r_b + Lc H4(xi) s_b
//   slope:     (H1'(xi) r_a + Lc H2'(xi) s_a + H3'(xi) r_b + Lc H4'(xi) s_b) / Lc
#pragma once
#include <petscsnes.h>

#include <array>
#include <vector>

#include "assembly/assembler.hpp"
#include "solvers/newton_test.hpp"

namespace sinew {

/// The PC type name of the cable coarse space (CableCoarseSpace::install).
#define PCCABLECOARSE "cablecoarse"
/// PCRegister of PCCABLECOARSE (main() at start-up; install() again, for library users).
PetscErrorCode registerCableCoarsePC();

class CableCoarseSpace {
 public:
  /// Coarse elements of about `ratio` fine elements along every split ancf_cable2d scene element.
  /// Collective (gathers the scene-element layout from all ranks).
  CableCoarseSpace(Assembler& assembler, int ratio);
  ~CableCoarseSpace();
  CableCoarseSpace(const CableCoarseSpace&) = delete;
  CableCoarseSpace& operator=(const CableCoarseSpace&) = delete;

  /// Makes `pc` this preconditioner; the fine LU is a KSP with options prefix "fine_" (MUMPS, or
  /// PETSc LU for ANCF-only models on one process; -fine_pc_factor_* changes it).
  /// Makes pc this coarse space's preconditioner: the registered PC type PCCABLECOARSE.
  PetscErrorCode install(PC pc);
  /// The PC type's set-up (fine LU of the preconditioning matrix, coarse matrix) and application.
  static PetscErrorCode setUp(PC pc);
  static PetscErrorCode apply(PC pc, Vec x, Vec y);
  int coarseNodes() const { return static_cast<int>(nodeCount_); }
  /// Coarse predictor (grid sequencing without a second mesh): solves the nonlinear problem in the
  /// coarse space, P^T F(U + P u) = 0, by Newton with Jacobian Ac (a SNES on the replicated coarse
  /// unknowns, options prefix "coarse_snes_"; every rank runs it in lock-step, its function is
  /// collective), and adds P u to U. The coarse space holds a cable of about sqrt(n)/2 Hermite
  /// elements, whose Newton path from a straight cable is as tame as a 1000-element cable's; the
  /// fine Newton then starts within the discretization error of that cable. On failure U is unchanged.
  PetscErrorCode predict(Vec U, const LoadState& ls);
  /// Coarse Newton iterations of all predictions so far.
  long predictorIterations() const { return predictorIts_; }
  /// Coarse set-ups (factorizations of Ac) and applications so far.
  long setups() const { return setups_; }
  long applications() const { return applications_; }
  /// Default ratio: fine elements per coarse element ~ 2 sqrt(total ANCF elements) (at least 8);
  /// 0 when no scene element is split into at least `minSplit` ANCF elements (no coarse space).
  static int defaultRatio(const DistributedMesh& mesh, int minSplit);

 private:
  PetscErrorCode restrictTo(Vec fine, Vec coarse);   // coarse = P^T fine (replicated)
  PetscErrorCode prolongAdd(Vec coarse, Vec fine);   // fine += P coarse (owned rows)
  PetscErrorCode coarseCorrection(Vec r, Vec y);     // y += P Ac^-1 P^T r
  PetscErrorCode assembleCoarse();
  static PetscErrorCode coarseFunction(SNES, Vec u, Vec r, void* ctx);
  static PetscErrorCode coarseJacobian(SNES, Vec u, Mat J, Mat P, void* ctx);
  SNES snes_ = nullptr;
  Vec U0_ = nullptr, Uw_ = nullptr, Fw_ = nullptr, uc_ = nullptr, fc_ = nullptr;
  LoadState ls_;
  long predictorIts_ = 0;
  static NewtonRules newtonRules();
  NewtonTest newtonTest_{newtonRules()};  ///< the coarse predictor's Newton test
  static PetscErrorCode coarseConverged(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                        SNESConvergedReason* reason, void* ctx);

  struct Row {  // one fine unknown: local index and its weights on 4 coarse unknowns
    int fine = -1;
    std::array<int, 4> coarse{};
    std::array<double, 4> w{};
  };
  Assembler& asm_;
  size_t nodeCount_ = 0;
  std::vector<char> fixed_;                     // per coarse unknown: constrained (not in the space)
  std::vector<Row> rows_;
  struct NodeMap {  // where a local fine node lies: coarse element (a, b), xi in [0, 1], length
    int a = -1, b = -1;
    double xi = 0, lc = 0;
  };
  std::vector<NodeMap> nodeMap_;                // per local node (owned and ghost)
  /// weights of fine coordinate k (x, y, slope_x, slope_y) of local node i on its 4 coarse unknowns
  void weights(int i, int k, std::array<int, 4>& coarse, std::array<double, 4>& w) const;
  std::vector<PetscInt> acRowStart_, acCols_;   // CSR pattern of Ac (same on every rank)
  std::vector<double> acValues_;
  Mat Ac_ = nullptr;
  KSP coarseKsp_ = nullptr, fineKsp_ = nullptr;
  Vec rc_ = nullptr, yc_ = nullptr, t1_ = nullptr, t2_ = nullptr;
  long setups_ = 0, applications_ = 0;
};

}  // namespace sinew
