// Modal state-space model (opt.transfer) of the converged state at load factor 1 (the end of the
// load stepping; the scene has no force/moment ramps, so this is the loaded state of prescribed
// motions and gravity). With the mass-normalized modes Phi (Phi^T M Phi = I) and circular
// frequencies Omega of ModalAnalysis, and x = [q; qdot] (u = Phi q):
//   A = [[0, I], [-Omega^2, -2 zeta Omega]],  B = [0; Phi^T b],  C = [c_d Phi, 0; 0, c_v Phi],  D = 0,
// b: unit loads of the transfer_in directions, c_d / c_v: selectors of displ_* / veloc_* outputs.
// Written once with ResultFile::writeArray: /statespace/A, B, C, D, plus /statespace/inputs and
// /statespace/outputs ([n, 2]: 1-based node, direction code 1..6 = force_x..moment_z resp.
// displ_x..veloc_z), /statespace/freq (Hz) and /statespace/zeta.
#pragma once
#include <string>
#include <vector>

#include "sinew/model.hpp"
#include "step/modal_analysis.hpp"

namespace sinew {

struct TransferChannel {
  int node = 0;  ///< 0-based scene node
  int code = 0;  ///< 0..5: force_x..moment_z (inputs), displ_x..veloc_z (outputs)
};

class StateSpaceAnalysis : public StepAnalysis {
 public:
  /// modal must be registered before this analysis (its modes are those of the same step).
  StateSpaceAnalysis(Assembler& assembler, const ModalAnalysis& modal, const Model& model, double zeta);
  const char* name() const override { return "state-space"; }
  PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) override;
  std::string summary() const override;
  std::string failure() const override { return failure_; }

 private:
  Assembler& asm_;
  const ModalAnalysis& modal_;
  double zeta_;
  std::vector<TransferChannel> in_, out_;
  bool written_ = false;
  int states_ = 0;
  std::string failure_;
};

}  // namespace sinew
