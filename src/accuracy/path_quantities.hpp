// -target_error for path following and form finding (docs/accuracy.md "Path following", "Form
// finding"): what a level of such a scene needs beyond the refinement of its mesh, and the quantities
// these analyses give.
//
// Path following (opt.continuation): every level follows the path to the scene's stop criterion
// (stop_displacement or stop_load_factor; max_steps x 2^level allows the finer levels' shorter steps
// in the arc-length metric, whose norm grows with the unknowns). Watched: the load factor of the k-th
// limit point and of the k-th bifurcation located on the coarsest level (/path/critical_points), and
// the end state, the node results and stress at the stop value exactly (cubic interpolation over the last path
// points, the last two straddling it), so the levels compare at the same point of the path.
//
// Form finding: watched is the found shape, the positions of the coarsest mesh's nodes (which every
// level keeps) on the last form-finding row; its error is their root-mean-square change relative to
// the model size.
#pragma once
#include <string>
#include <vector>

#include "accuracy/quantities.hpp"
#include "sinew/model.hpp"
#include "sinew/result_store.hpp"

namespace sinew::accuracy {

/// What the path levels cannot compare: "" or the reason (a path without a stop criterion ends at
/// max_steps, a different place of the path on every level).
std::string pathRefinementLimit(const Model& m);

/// The path options of level `level`: max_steps x 2^level (at most 100000); the stop criterion ends it.
void adaptPathLevel(Model& m, int level);

/// The results of a path whose last two rows straddle the scene's stop value, with the last row of
/// the load factor, control displacement, node results (p, r_quat, Freac, Mreac) and stressmax replaced
/// by their values at the stop value (cubic Lagrange interpolation in the stop variable over the last
/// four points along which it runs one way; rotation quaternions renormalized). Results of a scene without continuation are returned unchanged.
RunResults atPathStop(const Model& m, RunResults r);
/// The datasets atPathStop reads besides those of the quantities.
std::vector<std::string> pathStopDatasets(const Model& m);

/// Load factor of critical point `index` (0-based) of `kind` (1 limit, 2 bifurcation) in
/// /path/critical_points ([] when the level located fewer).
std::vector<double> criticalLoadFactor(const RunResults& r, int kind, long index);
/// Every limit and bifurcation point the coarsest level located, as quantities ("limit 1", "bifurcation 1").
void addCriticalPoints(std::vector<QuantityDef>& out, const RunResults& coarsest);

/// Positions of nodes 0..count-1 on the last form-finding row (/formfinding/step finite), the free
/// nodes only ([] without form-finding rows).
std::vector<double> formFoundShape(const RunResults& r, long count);
/// The scale of the shape's error: model size x sqrt(free nodes), so the error is the RMS node change
/// relative to the model size.
double shapeScale(const RunResults& r, long count);

}  // namespace sinew::accuracy
