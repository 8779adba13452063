// The spread of element stiffnesses in a model, for the constraint check's message: a mechanism found
// in a model whose stiffest element is more than 1/tol times stiffer than its softest one is more
// likely the round-off of the stiff element (a huge emod or area standing in for a rigid part) than a
// missing support.
#pragma once
#include <petscvec.h>

#include "assembly/assembler.hpp"

namespace sinew {

struct StiffnessSpread {
  /// largest and smallest positive translational diagonal entry of the element tangents (EA/L, 12 EI/L^3)
  double largest = 0.0, smallest = 0.0;
  int stiffest = -1, softest = -1;       ///< their scene elements (0-based)
  double ratio() const { return smallest > 0.0 ? largest / smallest : 0.0; }
};

/// Collective: the element tangents at state U (load state ls); elements without stiffness (rigid,
/// slack) are left out.
PetscErrorCode stiffnessSpread(Assembler& assembler, Vec U, const LoadState& ls, StiffnessSpread* spread);

}  // namespace sinew
