#include "app/progress.hpp"

#include <petscsys.h>

#include <cstdio>

namespace sinew {

namespace {
constexpr double kEstimateAfter = 2.0;  // seconds of a phase before its time left is estimated

std::string seconds(double s) {
  char buf[32];
  if (s < 100) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 6000) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}
}  // namespace

Progress::Progress(MPI_Comm comm, bool silent) : silent_(silent), start_(MPI_Wtime()), phaseStart_(start_) {
  MPI_Comm_rank(comm, &rank_);
}

void Progress::startPhase(const std::string& stepName, int total) {
  name_ = stepName;
  total_ = total;
  firstIndex_ = -1;
  phaseStart_ = MPI_Wtime();
}

void Progress::step(int index, const std::string& detail) {
  if (silent_ || rank_ != 0) return;
  if (firstIndex_ < 0) firstIndex_ = index;  // time step 0 (the initial state) takes no time
  const double now = MPI_Wtime(), inPhase = now - phaseStart_;
  std::string line = "  " + name_ + " " + std::to_string(index) + "/" + std::to_string(total_) + "  " + detail +
                     "  elapsed " + seconds(now - start_);
  const int done = index - firstIndex_ + 1, left = total_ - index;
  if (inPhase >= kEstimateAfter && left > 0 && done > 0) line += ", left ~" + seconds(inPhase / done * left);
  // through PETSc's printing (the library entry point keeps a run's output: sinew/simulation.hpp)
  PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT, "%s\n", line.c_str());
  std::fflush(stdout);
}

}  // namespace sinew
