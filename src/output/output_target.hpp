// The result file a run will write, checked before the analysis starts (rank 0 decides, every
// rank learns the outcome) and locked against a second run naming the same file.
#pragma once
#include <mpi.h>

#include <string>

namespace sinew {

/// Why `h5` cannot be this run's result file, or "": it is a directory, a device or another
/// non-regular file, the scene file itself (same inode; also for the XDMF beside it), or its
/// directory is missing. Local (call on rank 0).
std::string outputPathProblem(const std::string& h5, const std::string& scenePath);

/// An exclusive advisory lock (flock) on `<h5>.lock`, holding this process's pid. The operating
/// system releases it when the process ends, however it ends; a normal end also removes the file.
class OutputLock {
 public:
  OutputLock() = default;
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  /// Takes the lock (local). Returns "" or why not: another run holds it (its pid), or the
  /// directory is not writable.
  std::string acquire(const std::string& h5);
  void release();

 private:
  int fd_ = -1;
  std::string path_;
};

/// Whether another process holds the lock of `h5` (a run writing it): "" when none, else
/// "<h5> is being written by another run (pid N)". Local; does not create the lock file.
std::string otherWriter(const std::string& h5);

/// Collective: rank 0 checks the path and takes the lock; returns the problem ("" when none) on
/// every rank.
std::string claimOutput(MPI_Comm comm, const std::string& h5, const std::string& scenePath, OutputLock& lock);

}  // namespace sinew
