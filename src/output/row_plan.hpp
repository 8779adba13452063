// Distribution of the rows of a table, owned by the ranks in arbitrary order, into contiguous
// per-rank blocks: rank r holds the block [n r / P, n (r + 1) / P) of a table of n rows, so that
// each rank can write its block as one hyperslab. The plan (the all-to-all counts and the order of
// the rows) is built once per table and reused for every exchange of values over its rows. Used by
// the result file for node, element, mesh, cell and restart state tables.
#pragma once
#include <mpi.h>

#include <span>
#include <string>
#include <vector>

namespace sinew {

// Moves rows owned in arbitrary order to contiguous blocks, one block per rank.
struct RowPlan {
  long begin = 0, count = 0;          // this rank's block of the table
  std::vector<int> sendCounts, sendDispls, recvCounts, recvDispls;  // in rows
  std::vector<long> sendOrder;        // positions in the owned list, grouped by destination
  std::vector<long> recvSlot;         // block-local row of each received row
  bool complete = true;               // every row of every block is owned by some rank

  // The plan for a table of n rows of which this rank owns the global 0-based rows `owned` (each
  // row on at most one rank). Collective; a row outside [0, n) or owned by two ranks is an error
  // agreed on all ranks (std::runtime_error starting with `what`).
  static RowPlan build(MPI_Comm comm, long n, const std::vector<long>& owned, const std::string& what);

  // This rank's block, `m` values per row, from its owned rows (in owned order). Rows that no rank
  // owns are NaN.
  std::vector<double> exchange(MPI_Comm comm, std::span<const double> values, long m) const;
};

}  // namespace sinew
