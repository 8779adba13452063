// One level of a -target_error study in time hands its time steps to the next level, which halves dt
// (docs/accuracy.md, "Reuse between levels"): the coarse level records its converged state at every
// time step, and the fine level's Newton starts each step from that record at the step's end time, exact
// at the coarse times and a cubic Hermite in time between them, instead of the scheme's predictor.
// Levels in time alone have the same mesh, partition and unknowns: each rank records its own entries
// (dynamics/level_time_reuse.cpp). Levels that refine the elements too record the state and rates of
// every FE node on every rank (by node number, so independent of either level's partition); the fine
// level interpolates in time on the coarse nodes and maps the result onto its own nodes
// (StaticsHandover::coarseNodeMap, accuracy/level_reuse.hpp; dynamics/level_space_time_reuse.cpp).
#pragma once
#include <vector>

namespace sinew {

struct TimeHandover {
  /// One converged time step, this rank's part.
  struct Step {
    double t = 0;
    std::vector<double> q;          ///< owned entries of U (rotation increments 0: absorbed into R)
    std::vector<double> v;          ///< owned entries of the velocities (spatial angular velocities of Frame6 nodes)
    std::vector<double> rotations;  ///< unit quaternion R of every owned Frame6 node with rotation unknowns, in node order
  };
  /// One converged time step by FE node (every node, every rank; byNode).
  struct NodeStep {
    double t = 0;
    std::vector<double> states;  ///< 12 per FE node, LevelState's layout (x and R, x, or ANCF x, y, slopes)
    std::vector<double> rates;   ///< 6 per FE node: velocity and spatial angular velocity, or ANCF coordinates' rates
  };
  long firstOwnedUnknown = -1;  ///< the layout the steps belong to (this rank)
  std::vector<Step> steps;      ///< in time order, t = 0 first
  /// set by the study before the level runs: record nodeSteps instead of steps (the levels refine the elements)
  bool byNode = false;
  std::vector<int> nodeKinds;       ///< per FE node: its NodeKind (byNode)
  std::vector<NodeStep> nodeSteps;  ///< in time order, t = 0 first (byNode)
};

}  // namespace sinew
