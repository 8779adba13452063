// Collective agreement of the ranks on arguments and HDF5 outcomes (collective_agreement.hpp):
// the broadcasts of rank 0's shape and strings, the allreduce of argument errors with the
// signature check of a collective call, and the agreement on the status of an HDF5 call.
// Open MPI's deprecated C++ bindings warn under -Wcast-function-type when mpi.h is not a system
// header (plain -I from pkg-config); Sinew uses the C API only.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "output/collective_agreement.hpp"

#include <climits>
#include <functional>
#include <stdexcept>

#include "output/hdf5_util.hpp"
#include "output/io_diagnosis.hpp"
#include "sinew/result_file.hpp"

namespace sinew::collective {

long product(const std::vector<long>& v) {
  long p = 1;
  for (long x : v) p *= x;
  return p;
}

std::string broadcastShape(MPI_Comm comm, std::size_t numValues, std::vector<long>& shape, long minDim) {
  long header[2] = {static_cast<long>(shape.size()), static_cast<long>(numValues)};
  MPI_Bcast(header, 2, MPI_LONG, 0, comm);
  shape.resize(static_cast<std::size_t>(header[0]));
  MPI_Bcast(shape.data(), static_cast<int>(shape.size()), MPI_LONG, 0, comm);
  for (long d : shape)
    if (d < minDim) return minDim == 0 ? "negative dimension" : "dimension < " + std::to_string(minDim);
  if (product(shape) != header[1]) return std::to_string(header[1]) + " values on rank 0 for " + std::to_string(product(shape));
  return "";
}

std::string broadcastString(MPI_Comm comm, const std::string& s) {
  long n = static_cast<long>(s.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, comm);
  std::string out = s;
  out.resize(static_cast<std::size_t>(n));
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, comm);
  return out;
}

void agree(MPI_Comm comm, const std::string& localError, std::size_t signature, const std::string& what) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const long sig = static_cast<long>(signature & 0x3fffffffffffffffULL);
  long buf[3] = {localError.empty() ? LONG_MIN : -static_cast<long>(rank), sig, -sig};
  MPI_Allreduce(MPI_IN_PLACE, buf, 3, MPI_LONG, MPI_MAX, comm);
  if (!localError.empty()) throw std::runtime_error(what + ": " + localError);
  if (buf[0] != LONG_MIN) throw std::runtime_error(what + ": invalid arguments on rank " + std::to_string(-buf[0]));
  if (buf[1] != -buf[2]) throw std::runtime_error(what + ": ranks disagree on the name or shape of a collective write");
}

std::size_t signatureOf(const std::string& name, const std::vector<long>& dims, int kind) {
  std::size_t h = std::hash<std::string>{}(name) ^ (std::size_t(kind) * 0x9e3779b97f4a7c15ULL);
  for (long d : dims) h = h * 1000003ULL ^ std::hash<long>{}(d);
  return h;
}

void agreeStatus(MPI_Comm comm, long status, const std::string& what, const std::string& file) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string msg;
  if (status < 0) {
    msg = h5::failureText(what);
    const std::string cause = ioFailureCause(file);
    if (!cause.empty()) msg += ": " + cause;
  }
  int first = status < 0 ? rank : INT_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return;
  long n = static_cast<long>(msg.size());
  MPI_Bcast(&n, 1, MPI_LONG, first, comm);
  msg.resize(static_cast<std::size_t>(n));
  MPI_Bcast(msg.data(), static_cast<int>(n), MPI_CHAR, first, comm);
  throw ResultFileError("file " + file + ": " + msg);
}

}  // namespace sinew::collective
