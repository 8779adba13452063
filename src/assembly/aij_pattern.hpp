// The nonzero pattern of a one-process AIJ matrix (its CSR row starts and columns, as MatGetRowIJ
// gives them) compared with a pattern kept from an earlier matrix.
#pragma once

#include <petscmat.h>

#include <algorithm>
#include <vector>

namespace sinew {

/// True when the CSR pattern (ia, ja) of an n-row matrix is (rowStart, cols).
inline bool samePattern(PetscInt n, const PetscInt* ia, const PetscInt* ja, const std::vector<PetscInt>& rowStart,
                        const std::vector<PetscInt>& cols) {
  return std::equal(ia, ia + n + 1, rowStart.begin(), rowStart.end()) &&
         std::equal(ja, ja + ia[n], cols.begin(), cols.end());
}

}  // namespace sinew
