// Progress lines of a batch run: one line per converged form-finding step, load step or written
// time step, printed and flushed by rank 0 as the step finishes, with the wall time since the
// start and, once a phase has run for a while, an estimate of the time it has left.
#pragma once
#include <mpi.h>

#include <string>

namespace sinew {

class Progress {
 public:
  /// silent: print nothing (opt.silent).
  Progress(MPI_Comm comm, bool silent);
  /// Elapsed times count from `t` (MPI_Wtime() at the start of the run).
  void setStart(double t) { start_ = t; }
  /// A new phase of `total` steps ("load step", "time step", "form-finding step").
  void startPhase(const std::string& stepName, int total);
  /// Step `index` (1-based) of the phase converged; `detail` goes in the middle of the line.
  void step(int index, const std::string& detail);

 private:
  int rank_ = 0;
  bool silent_ = false;
  double start_ = 0, phaseStart_ = 0;
  int total_ = 0, firstIndex_ = 1;
  std::string name_;
};

}  // namespace sinew
