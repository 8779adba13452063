// Why writing a file failed, in words a user can act on (HDF5 and MPI-IO only say "write failed").
#pragma once
#include <string>

namespace sinew {

/// "no space left on device (N bytes free on the file system of DIR)" when that file system is
/// (nearly) full, "file size limit reached (ulimit -f: N bytes)" when `path` has reached the
/// process's RLIMIT_FSIZE, else "".
std::string ioFailureCause(const std::string& path);

}  // namespace sinew
