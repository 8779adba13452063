#include "output/output_target.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace sinew {

namespace {

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string readPid(int fd) {
  char buf[32] = "";
  const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
  std::string s(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

std::string outputPathProblem(const std::string& h5, const std::string& scenePath) {
  namespace fs = std::filesystem;
  if (h5.empty()) return "the result file name is empty";
  if (h5.back() == '/') return h5 + " is a directory, not a file name";
  struct stat st {};
  if (stat(h5.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return h5 + " is a directory, not a file name";
    if (!S_ISREG(st.st_mode)) return h5 + " is not a regular file (a device, FIFO or socket); name a file";
  }
  const std::string xdmf = fs::path(h5).replace_extension(".xdmf").string();
  if (sameFile(h5, scenePath)) return "-o " + h5 + " is the scene file itself; name another result file";
  if (sameFile(xdmf, scenePath))
    return "the XDMF file " + xdmf + " beside the result would replace the scene file; name another result file";
  if (stat(xdmf.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    return "the XDMF file " + xdmf + " beside the result would replace a directory or device";
  const fs::path parent = fs::path(h5).parent_path();
  const std::string dir = parent.empty() ? fs::path(".").string() : parent.string();
  if (stat(dir.c_str(), &st) != 0) return "the directory " + dir + " of " + h5 + " does not exist";
  if (!S_ISDIR(st.st_mode)) return dir + " (the directory of " + h5 + ") is not a directory";
  return "";
}

OutputLock::~OutputLock() { release(); }

std::string OutputLock::acquire(const std::string& h5) {
  release();
  const std::string path = h5 + ".lock";
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) return "cannot create " + path + " (" + std::strerror(errno) + "): the directory is not writable";
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string pid = readPid(fd);
      close(fd);
      if (err == EWOULDBLOCK)
        return h5 + " is being written by another run" + (pid.empty() ? "" : " (pid " + pid + ")") +
               "; wait for it or name another result file with -o";
      return "cannot lock " + path + ": " + std::strerror(err);
    }
    // The holder before us may have removed the lock file after we opened it: then our lock is on
    // an unlinked file, and a third run could lock a new one. Retry on the current file.
    struct stat a {}, b {};
    if (fstat(fd, &a) != 0 || stat(path.c_str(), &b) != 0 || a.st_ino != b.st_ino || a.st_dev != b.st_dev) {
      close(fd);
      continue;
    }
    const std::string pid = std::to_string(getpid()) + "\n";
    if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
      const int err = errno;
      close(fd);
      return "cannot write " + path + ": " + std::strerror(err);
    }
    fd_ = fd;
    path_ = path;
    return "";
  }
  return "cannot lock " + path + ": it keeps being replaced";
}

void OutputLock::release() {
  if (fd_ < 0) return;
  unlink(path_.c_str());  // while still holding the lock (see acquire)
  close(fd_);
  fd_ = -1;
}

std::string otherWriter(const std::string& h5) {
  const std::string path = h5 + ".lock";
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "";  // no lock file: no run has it open (a run creates it before its first write)
  std::string busy;
  if (flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    const std::string pid = readPid(fd);
    busy = h5 + " is being written by another run" + (pid.empty() ? "" : " (pid " + pid + ")");
  }
  close(fd);  // releases a shared lock taken here
  return busy;
}

std::string claimOutput(MPI_Comm comm, const std::string& h5, const std::string& scenePath, OutputLock& lock) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string problem;
  if (rank == 0) {
    problem = outputPathProblem(h5, scenePath);
    if (problem.empty()) problem = lock.acquire(h5);
  }
  long n = static_cast<long>(problem.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  problem.resize(static_cast<std::size_t>(n));
  MPI_Bcast(problem.data(), static_cast<int>(n), MPI_CHAR, 0, comm);
  return problem;
}

}  // namespace sinew
