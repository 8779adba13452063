// An analysis evaluated at converged steps (frequencies, buckling, compliance...): at the written rows
// opt.step_analyses selects (RunContext::writeStep), sensors at every written row.
#pragma once
#include <petscvec.h>

#include <string>

#include "assembly/assembler.hpp"
#include "sinew/result_file.hpp"

namespace sinew {

class StepAnalysis {
 public:
  virtual ~StepAnalysis() = default;
  virtual const char* name() const = 0;
  /// Runs at the converged state U of the current step (file.beginStep done). Sets ok = false
  /// with a message in failure() when it cannot produce its result.
  virtual PetscErrorCode atStep(Vec U, const LoadState& ls, ResultFile& file, bool* ok) = 0;
  /// true: runs at every written row (sensors: output, not an analysis); false: at the rows
  /// opt.step_analyses selects (frequencies, buckling, compliance, state space).
  virtual bool everyRow() const { return false; }
  /// Lines for the stdout summary (rank 0 prints them).
  virtual std::string summary() const { return {}; }
  virtual std::string failure() const { return {}; }
};

}  // namespace sinew
