// Collective agreement of the ranks on the arguments and outcome of a collective write, used by the
// result file (result_file.cpp) and its row plans (row_plan.hpp): every rank learns whether any
// rank found an invalid argument or had an HDF5 call fail, so that all of them throw together and
// none is left waiting in a collective HDF5 call; rank 0's values (a shape, a string) reach every
// rank. Every function here is collective over `comm`.
#pragma once
#include <mpi.h>

#include <cstddef>
#include <string>
#include <vector>

namespace sinew::collective {

/// Number of values of an array of the given shape (1 for an empty shape).
long product(const std::vector<long>& v);

// writeArray/writeStateArray: rank 0's shape and number of values reach every rank (the others'
// arguments are ignored); "" or what is wrong with them (a dimension below minDim, a count that is
// not the shape's product).
std::string broadcastShape(MPI_Comm comm, std::size_t numValues, std::vector<long>& shape, long minDim);

/// Rank 0's string, on every rank.
std::string broadcastString(MPI_Comm comm, const std::string& s);

// Every rank learns whether any rank failed a check, so all of them throw together. `signature`
// must be equal on all ranks (name and shape of a collective call); a mismatch is an error too.
void agree(MPI_Comm comm, const std::string& localError, std::size_t signature, const std::string& what);

/// Hash of the name, the shape and the kind of a collective call (the `signature` of agree).
std::size_t signatureOf(const std::string& name, const std::vector<long>& dims, int kind);

// Every rank learns whether an HDF5 call failed on any rank (a full disk may fail the write of
// one aggregator only); all throw the message of the first failing rank, so none is left waiting
// in the next collective call.
// `status` < 0: this rank failed; the error names the file `file` and the cause (ResultFileError).
void agreeStatus(MPI_Comm comm, long status, const std::string& what, const std::string& file);

}  // namespace sinew::collective
