// What a path-following run reports when its loop has ended (issue 24): why it stopped, stored as
// the /path attribute stop_reason, whether that is short of the end the scene asked for (exit 3),
// and whether the path turned back on itself. Plain functions of the path points' load factors and
// control displacements (no PETSc), so they are unit-tested alone (tests/unit/test_path_report.cpp).
#pragma once
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace sinew {

/// Why a path ended after `points` points at load factor `lambda` and control displacement `u`.
struct PathEnd {
  std::string reason;     ///< "stop_displacement -0.02 reached", "max_steps 200 reached before stop_displacement -0.02", ...
  bool endedShort = false;  ///< max_steps ended it before the stop_load_factor / stop_displacement the scene gave
};

/// failed: a corrector that did not converge ended the loop; interrupted: a signal (or a failed write).
PathEnd pathEnd(const ContinuationOptions& c, int points, double lambda, double u, bool failed, bool interrupted);

/// A stretch of the path that runs back along an earlier one in the plane of the load factor and the
/// control displacement (each scaled by its largest magnitude along the path): two consecutive steps
/// ending within a fifth of their length of an earlier step that went the opposite way (cosine below
/// -0.95; among the 50 steps before, where a path that turns back runs first). A snap-back loop
/// crosses itself at an angle and is no retrace. point: the first retracing
/// point (0-based index), earlier: the first point of the step it retraces; -1 when none (also
/// without a control displacement).
struct PathRetrace {
  int point = -1, earlier = -1;
};
PathRetrace pathRetrace(const std::vector<double>& lambda, const std::vector<double>& u);

/// A path whose followed displacement turns back after a limit point (the load factor's first
/// maximum) and runs back over more than half of the way it had gone from the start (a snap-back
/// turns back over a small part of it), along the way it came: the median distance of the points
/// on the way back from the way there (after the limit point), in the plane of the load factor and
/// the displacement scaled by their largest magnitudes, is below 0.05. It revisits states of that
/// way. A way back at other load factors is another branch (a pinned shallow arch's symmetric path
/// loops so: tests/cases/test_continuation_shallow_arch.py) and no turn-back. limit, turn and
/// back are 0-based point indices (the limit point, the farthest point before the turn, the end of
/// the way back); -1 when none.
struct PathTurnBack {
  int limit = -1, turn = -1, back = -1;
  double fraction = 0;  ///< the way back over the way there
};
PathTurnBack pathTurnBack(const std::vector<double>& lambda, const std::vector<double>& u);

}  // namespace sinew
