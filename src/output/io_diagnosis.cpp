#include "output/io_diagnosis.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

#include <filesystem>

namespace sinew {

std::string ioFailureCause(const std::string& path) {
  constexpr unsigned long long kNearlyFull = 1ULL << 20;  // less than one HDF5 chunk can still fit
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string dir = parent.empty() ? std::string(1, '.') : parent.string();  // (GCC 12 -Wrestrict false positive on dir = ".")
  struct statvfs fs {};
  if (statvfs(dir.c_str(), &fs) == 0) {
    const unsigned long long freeBytes = static_cast<unsigned long long>(fs.f_bavail) * fs.f_frsize;
    if (freeBytes < kNearlyFull)
      return "no space left on device (" + std::to_string(freeBytes) + " bytes free on the file system of " + dir + ")";
  }
  struct rlimit lim {};
  struct stat st {};
  if (getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY && stat(path.c_str(), &st) == 0 &&
      static_cast<unsigned long long>(st.st_size) + kNearlyFull >= static_cast<unsigned long long>(lim.rlim_cur))
    return "file size limit reached (ulimit -f: " + std::to_string(static_cast<unsigned long long>(lim.rlim_cur)) +
           " bytes)";
  return "";
}

}  // namespace sinew
