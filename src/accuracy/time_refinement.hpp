// Accuracy on demand in time (opt.target_error with opt.dynamics, docs/accuracy.md "Dynamics"):
// level L runs the scene with the time step dt / 2^L and the same mesh, writing the same times
// (output_every and output_steps scaled by 2^L), so every level's rows are at the same times. The
// quantities are time histories: the displacement of a watched node at every written row, its error
// the worst over the rows (accuracy/richardson.hpp with rows of 3 components). Every scheme of
// src/dynamics (Arnold-Brüls generalized-alpha, midpoint, energy-momentum, PETSc's TSALPHA2) is second
// order in dt. Adaptive steps (opt.dynamics.adaptive) choose their own steps: refused.
// opt.accuracy_refine chooses what the levels of a dynamics scene refine: time (the default), space
// (the elements as in statics, dt as written) or both (elements and dt halved together; the order of
// a history is then the lower of the two).
#pragma once
#include <string>
#include <vector>

#include "accuracy/quantities.hpp"
#include "sinew/model.hpp"
#include "sinew/result_store.hpp"

namespace sinew::accuracy {

/// The order in dt of every time scheme Sinew has.
constexpr double kTimeSchemeOrder = 2.0;

/// The scene's levels halve the time step (opt.dynamics, opt.accuracy_refine time or both).
bool refinesTime(const Model& m);
/// The scene's levels refine the elements (no opt.dynamics, or opt.accuracy_refine space or both).
bool refinesSpace(const Model& m);
/// "" or why -target_error cannot refine the time steps of this scene (a scene error): adaptive
/// steps, quantities other than histories, opt.accuracy_refine time or both without opt.dynamics.
std::string timeRefinementLimit(const Model& m);
/// Level `level` in time: dt / 2^level, rows written at the same times as level 0 (the mesh of `base`).
Model timeRefinedModel(const Model& base, int level);
/// Time steps of a run of `m` (tend / dt rounded up, as the time loop counts them).
long timeSteps(const Model& m);

/// The time histories watched: `names` ("node <n> p") or the loaded nodes and the node that moves
/// most over the rows of the coarsest level (with the elements refined: among the scene's nodes, which
/// every level keeps).
std::vector<QuantityDef> historyQuantities(const Model& model, const RunResults& coarsest,
                                           const std::vector<std::string>& names);
/// Displacement of `node` at every row, [rows x 3] flattened (empty when node/p is missing).
std::vector<double> displacementHistory(long node, const RunResults& r);
/// The largest displacement of any node at any row (the histories' scale; 0 when none).
double largestDisplacementOverRows(const RunResults& r);
/// A history as printed: its rows and its last row.
std::string historyText(const std::vector<double>& v);

}  // namespace sinew::accuracy
