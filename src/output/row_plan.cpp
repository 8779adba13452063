// Row plans (row_plan.hpp): building the all-to-all exchange that moves owned rows to the
// contiguous per-rank blocks of a table, and exchanging values along it.
// Open MPI's deprecated C++ bindings warn under -Wcast-function-type when mpi.h is not a system
// header (plain -I from pkg-config); Sinew uses the C API only.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include "output/row_plan.hpp"

#include <algorithm>
#include <limits>

#include "output/collective_agreement.hpp"

namespace sinew {

using collective::agree;
using collective::signatureOf;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

RowPlan RowPlan::build(MPI_Comm comm, long n, const std::vector<long>& owned, const std::string& what) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  RowPlan p;
  std::string error;
  for (long g : owned)
    if (g < 0 || g >= n) {
      error = "row " + std::to_string(g) + " outside [0, " + std::to_string(n) + ")";
      break;
    }
  agree(comm, error, signatureOf(what, {n}, 0), what);

  std::vector<long> begins(size + 1);
  for (int r = 0; r <= size; ++r) begins[r] = n * r / size;
  p.begin = begins[rank];
  p.count = begins[rank + 1] - begins[rank];
  std::vector<int> dest(owned.size());
  p.sendCounts.assign(size, 0);
  for (std::size_t i = 0; i < owned.size(); ++i) {
    dest[i] = static_cast<int>(std::upper_bound(begins.begin(), begins.end(), owned[i]) - begins.begin()) - 1;
    ++p.sendCounts[dest[i]];
  }
  p.recvCounts.assign(size, 0);
  MPI_Alltoall(p.sendCounts.data(), 1, MPI_INT, p.recvCounts.data(), 1, MPI_INT, comm);
  p.sendDispls.assign(size, 0);
  p.recvDispls.assign(size, 0);
  for (int r = 1; r < size; ++r) {
    p.sendDispls[r] = p.sendDispls[r - 1] + p.sendCounts[r - 1];
    p.recvDispls[r] = p.recvDispls[r - 1] + p.recvCounts[r - 1];
  }
  const long received = size ? p.recvDispls[size - 1] + p.recvCounts[size - 1] : 0;
  p.sendOrder.resize(owned.size());
  std::vector<long> sendRows(owned.size());
  std::vector<int> fill = p.sendDispls;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int slot = fill[dest[i]]++;
    p.sendOrder[slot] = static_cast<long>(i);
    sendRows[slot] = owned[i];
  }
  p.recvSlot.resize(received);
  MPI_Alltoallv(sendRows.data(), p.sendCounts.data(), p.sendDispls.data(), MPI_LONG, p.recvSlot.data(),
                p.recvCounts.data(), p.recvDispls.data(), MPI_LONG, comm);
  std::vector<char> seen(p.count, 0);
  for (long& r : p.recvSlot) {
    r -= p.begin;
    if (seen[r]++ && error.empty()) error = "row " + std::to_string(r + p.begin) + " is owned by two ranks";
  }
  int complete = std::all_of(seen.begin(), seen.end(), [](char c) { return c != 0; });
  MPI_Allreduce(MPI_IN_PLACE, &complete, 1, MPI_INT, MPI_LAND, comm);
  p.complete = complete != 0;
  agree(comm, error, signatureOf(what, {n}, 1), what);
  return p;
}

std::vector<double> RowPlan::exchange(MPI_Comm comm, std::span<const double> values, long m) const {
  std::vector<double> send(values.size()), recv(recvSlot.size() * m), block(count * m, kNaN);
  for (std::size_t i = 0; i < sendOrder.size(); ++i)
    std::copy_n(values.begin() + sendOrder[i] * m, m, send.begin() + static_cast<long>(i) * m);
  MPI_Datatype row;
  MPI_Type_contiguous(static_cast<int>(m), MPI_DOUBLE, &row);
  MPI_Type_commit(&row);
  MPI_Alltoallv(send.data(), sendCounts.data(), sendDispls.data(), row, recv.data(), recvCounts.data(),
                recvDispls.data(), row, comm);
  MPI_Type_free(&row);
  for (std::size_t i = 0; i < recvSlot.size(); ++i)
    std::copy_n(recv.begin() + static_cast<long>(i) * m, m, block.begin() + recvSlot[i] * m);
  return block;
}

}  // namespace sinew
