// One level of a -target_error study hands its load-stepped statics to the next, finer level
// (docs/accuracy.md, "Reuse between levels"): the coarse level records its converged state at every
// accepted load increment; the study interpolates those states onto the fine level's nodes
// (accuracy/level_reuse.hpp), and the fine level's Newton starts each increment that ends at a
// recorded load factor from that state instead of the last converged one (or the predictor). Levels
// in time hand on their time steps instead (analysis/time_handover.hpp).
#pragma once
#include <petscvec.h>

#include <functional>
#include <memory>
#include <vector>

#include "analysis/time_handover.hpp"

namespace sinew {

class Assembler;

/// Node states of every FE node of a level, 12 doubles per node in FE node order (gid): x and the
/// rotation R (row-major) of a Frame6 node, x alone of a Point3 node, (x, y, slope x, slope y) of an
/// ANCF node (Assembler::nodeState's layout).
struct LevelState {
  double loadFactor = 0;
  std::vector<double> nodes;
};

struct StaticsHandover {
  /// written by the level's statics: the converged state of every accepted increment, in order
  std::vector<LevelState> record;
  /// read by the level's statics: the coarser level's states on this level's nodes (empty: none)
  std::vector<LevelState> guesses;
  /// increments (path steps, time steps) whose Newton started from a guess and converged (this level's run)
  int guessesUsed = 0;
  /// dynamics, levels in time (analysis/time_handover.hpp): written by the level's time loop when set
  std::shared_ptr<TimeHandover> history;
  /// read by the level's time loop: the coarser level's time steps (null: none)
  std::shared_ptr<const TimeHandover> coarseHistory;
  /// levels that refine the elements (coarseHistory->byNode): the coarser level's node states (12 per FE
  /// node) on this level's FE nodes (accuracy/level_reuse.hpp, LevelNodeMap; empty answer: no map)
  std::function<std::vector<double>(const std::vector<double>&)> coarseNodeMap;
  /// path steps that followed the coarser level's step plan and converged (this level's run)
  int plannedSteps = 0;
  /// the load analysis after form finding (accuracy/found_shape_reuse.hpp): the level records `start`, its
  /// statics' or path's start state (its found shape), and its guesses hold displacements from that start,
  /// which the statics or the path adds to its own start (the positions of Point3 nodes; set by the study)
  bool fromStart = false;
  LevelState start;
};

/// The node states of the assembler's current evaluation (every FE node, every rank) at load factor
/// lambda (collective).
PetscErrorCode gatherLevelState(const Assembler& assembler, double lambda, LevelState* state);
/// The state `start` moved by the displacement d (StaticsHandover::fromStart; its positions, the first
/// three doubles of each node, added to start's): this level's found shape plus a coarser displacement.
LevelState displacedFrom(const LevelState& start, const LevelState& d);
/// U <- the state g on the free DOFs (rotations relative to the assembler's reference rotations); the
/// other entries of U stay.
PetscErrorCode setUnknownsFromState(const Assembler& assembler, const LevelState& g, Vec U);

}  // namespace sinew
