// One level of a -target_error study in time hands its time steps to the next level, which halves dt
// (docs/accuracy.md, "Reuse between levels"): the coarse level records its converged state at every
// time step, each rank its own entries (both levels have the same mesh, partition and unknowns), and
// the fine level's Newton starts each step from that record at the step's end time, exact at the coarse
// times and a cubic Hermite in time between them (dynamics/level_time_reuse.cpp), instead of the
// scheme's predictor.
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
  long firstOwnedUnknown = -1;  ///< the layout the steps belong to (this rank)
  std::vector<Step> steps;      ///< in time order, t = 0 first
};

}  // namespace sinew
